#pragma once
// What QEPCAD B and Z3 answer, read from their output: empty / non-empty / unknown with the reason, and a
// sample point of a non-empty set (QEPCAD's d-witness-list, Z3's model) when they print one.
#include "theory/logic/polynomial.hpp"

#include <optional>
#include <string>
#include <vector>

namespace affinterp::proofs {

enum class SetResult { empty, non_empty, unknown };

/// "empty", "non-empty", "unknown".
std::string_view to_string(SetResult r);

/// A sample point of the set as a decider printed it. Algebraic coordinates (QEPCAD's "alpha", Z3's
/// root-obj) are rational approximations, and `exact` is then false.
struct Witness {
  logic::Point point;
  bool exact = true;
};

struct DeciderAnswer {
  SetResult result = SetResult::unknown;
  std::string reason;              ///< why unknown, one line
  std::optional<Witness> witness;  ///< a point of the set, when non-empty and printed
};

/// QEPCAD B's answer to a sentence over `variables` (its variable list, in order): "TRUE" is non-empty,
/// "FALSE" empty; the witness from d-witness-list ("Coordinate i = …"). An output with an error, a warning or a
/// failure anywhere ("Error! Delineating polynomial …", the McCallum projection warning, "Prime list
/// exhausted", "Too few cells reclaimed", std::bad_alloc at the address-space cap) or no answer is unknown.
DeciderAnswer parse_qepcad(const std::string& output, const std::vector<std::string>& variables);

/// An SMT solver's answer (`tool`: "z3", "cvc5"): sat (non-empty, with the model's values: decimals, (- a),
/// (/ a b), root-obj), unsat (empty); unknown, a timeout, or an error or warning anywhere: unknown.
DeciderAnswer parse_smt(const std::string& output, std::string_view tool);

/// The decider's output without the lines that vary run to run (QEPCAD's timings), so that the committed
/// .out files change only when the answer does.
std::string without_timings(const std::string& output);

}  // namespace affinterp::proofs
