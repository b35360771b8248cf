#pragma once
// Polynomial and rational identities as parts of a proof (issue 10): lhs = rhs for all values of the symbols
// where both sides are defined, decided by two independent checkers,
//   ginac       GiNaC's normal() of lhs − rhs is 0 (polynomial arithmetic and gcd cancellation), and
//   exact-grid  exact integer evaluation of the unexpanded sides on a grid large enough for their degree
//               (exact_grid.hpp), which shares no arithmetic with GiNaC.
// Both read the sides back from the text of a ginsh script, <name>.ginsh, written first: one line
// `is(normal((lhs) - (rhs)) == 0);` per entry, which `ginsh <name>.ginsh` answers with 1 (holds) or 0, so anyone
// can rerun it with GiNaC's own shell; <name>.ginsh.out holds those answers and <name>.grid.out the grid
// checker's bounds and result.
#include "experiments/claims/outcome.hpp"

#include <ginac/ginac.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::proofs {

struct Identity {
  std::string name;     ///< the file stem, e.g. "complete-square"
  std::string meaning;  ///< one line: what lhs = rhs says, in words
  /// Both sides built from the suite's own algebra (theory/) over symbols, not expanded; matrices (GiNaC::matrix)
  /// compare entry by entry. Distinct symbols must have distinct names (the script names them).
  GiNaC::ex lhs, rhs;
};

/// Where a proof's files go.
struct SentenceFiles {
  std::filesystem::path dir;  ///< written here; empty: nothing is written
  std::string reference;      ///< how claims.json names `dir`, e.g. "proofs/kaji.er.closed-form"
};

/// Decides `identity` with both checkers and writes its files into `files.dir` (when set). The sentence's result
/// is "zero" (the identity holds) or "non-zero" (it fails: lhs − rhs is a nonzero rational function). Throws
/// std::runtime_error when the checkers disagree, std::invalid_argument on an expression neither can read.
claims::ProofSentence prove_identity(const Identity& identity, const SentenceFiles& files);

/// prove_identity of each, in order.
std::vector<claims::ProofSentence> prove_identities(const std::vector<Identity>& identities,
                                                    const SentenceFiles& files);

/// A proof of identities alone, checked by {"ginac", "exact-grid"}.
claims::Proof identity_proof(std::string scope, std::string method, std::vector<claims::ProofSentence> sentences);

/// Whether every sentence has `result` ("zero" for identities, "empty" for sentences).
bool all_results(const std::vector<claims::ProofSentence>& sentences, std::string_view result);

}  // namespace affinterp::proofs
