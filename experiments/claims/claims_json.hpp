#pragma once
// The claims.json document: the machine-readable result of a run, from which the report is made.
#include "experiments/claims/context.hpp"
#include "experiments/claims/runner.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace affinterp::claims {

/// One claim's entry: id, where, statement, verdict, summary, evidence, counterexample, correction,
/// figures, seconds.
nlohmann::json to_json(const ClaimResult& result);

/// The global engine's tables as the run measured them: experiments/measurements/'s EngineSpeed, EngineScale and
/// EngineCli as JSON (null: not measured).
struct EngineTables {
  nlohmann::json speed, scale, cli, engine3, engine3_scale, engine3_quality;
};

/// The whole document, one entry per claim of `registry` in run order, and the engine's tables. When `previous`
/// is an earlier document, its entries for claims not in `results` are kept, so that a run with --only updates
/// just those claims.
nlohmann::json claims_document(const ClaimRegistry& registry, const std::vector<ClaimResult>& results,
                               const RunContext& context, const nlohmann::json& environment,
                               const nlohmann::json& previous, const EngineTables& engine);

}  // namespace affinterp::claims
