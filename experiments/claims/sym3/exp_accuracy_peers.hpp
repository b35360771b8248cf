#pragma once
// thesis.exp.accuracy's evidence about the algorithms themselves: one matrix's case (S exactly, the result,
// the certified reference, the judgement) and the peer table (per family and algorithm the worst certified
// error and the counts of failures, with one matrix for each kind of failure).
#include "experiments/claims/sym3/exp_accuracy_sweep.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace affinterp::claims::sym3 {

/// A result is "wrong" in the peer table when its certified relative error exceeds this (fewer than six
/// correct digits: the thesis's own accuracy bar).
constexpr double kWrong = 1e-6;

/// An error for claims.json: the number, or a note where a result was not finite (JSON has no ∞).
nlohmann::json error_json(double error);

/// x with two significant digits in scientific notation.
std::string short_number(double x);

/// One matrix's evidence: S (rows of doubles and their exact values), eigenvalues, the result E of
/// `algorithm`, the certified reference (midpoint and Frobenius radius) and the judgement with its certified error.
nlohmann::json matrix_case(const Mat3& S, const std::string& algorithm, const Mat3& E, const CertifiedTruth& truth);
/// The same, running `algorithm` on S and certifying exp S.
nlohmann::json matrix_case(const Mat3& S, const NamedExpBatch& algorithm);

struct PeerTable {
  nlohmann::json data = nlohmann::json::object();      ///< family → algorithm → numbers
  nlohmann::json failures = nlohmann::json::object();  ///< algorithm → kind → {count, families, example}
  nlohmann::json markdown;                             ///< {title, columns, rows} for the report
};

PeerTable peer_table(const std::vector<FamilySweep>& sweeps, const std::vector<NamedExpBatch>& algorithms);

}  // namespace affinterp::claims::sym3
