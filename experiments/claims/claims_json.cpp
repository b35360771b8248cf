#include "experiments/claims/claims_json.hpp"

#include "experiments/claims/engine_speed.hpp"

#include <chrono>
#include <ctime>

namespace affinterp::claims {

namespace {

nlohmann::json optional_json(const auto& value) { return value ? nlohmann::json(*value) : nlohmann::json(nullptr); }

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

nlohmann::json to_json(const ClaimResult& result) {
  const Outcome& o = result.outcome;
  const Evidence& e = o.evidence;
  return {
      {"id", result.claim->id},
      {"group", report_section(result.claim->chapter)},
      {"where", result.claim->where},
      {"statement", result.claim->statement},
      {"verdict", to_string(o.verdict)},
      {"summary", o.summary},
      {"evidence",
       {{"method", e.method},
        {"sample_size", e.sample_size},
        {"seed", optional_json(e.seed)},
        {"tolerance", optional_json(e.tolerance)},
        {"worst_deviation", optional_json(e.worst_deviation)},
        {"details", e.details},
        {"measurements", e.measurements}}},
      {"counterexample", o.counterexample},
      {"correction", optional_json(o.correction)},
      {"figures", o.figures},
      {"seconds", result.seconds},
  };
}

nlohmann::json claims_document(const ClaimRegistry& registry, const std::vector<ClaimResult>& results,
                               const RunContext& context, const nlohmann::json& environment,
                               const nlohmann::json& previous) {
  nlohmann::json claims = nlohmann::json::array();
  for (const Claim& claim : registry.claims()) {
    const nlohmann::json* entry = nullptr;
    nlohmann::json fresh;
    for (const auto& r : results)
      if (r.claim->id == claim.id) entry = &(fresh = to_json(r));
    if (entry == nullptr && previous.contains("claims"))
      for (const auto& old : previous["claims"])
        if (old.value("id", "") == claim.id) entry = &old;
    if (entry != nullptr) claims.push_back(*entry);
  }
  return {
      {"tool", "affinterp"},
      {"generated_at", utc_now()},
      {"seed", context.seed},
      {"size", to_string(context.size)},
      {"environment", environment},
      {"claims", claims},
      {"engine_speed", engine_speed(context.bench_dir / "bench_interp.json")},
  };
}

}  // namespace affinterp::claims
