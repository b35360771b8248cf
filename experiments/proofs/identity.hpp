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

namespace affinterp::proofs {

struct Identity {
  std::string name;     ///< the file stem, e.g. "complete-square"
  std::string meaning;  ///< one line: what lhs = rhs says, in words
  /// Both sides built from the suite's own algebra (theory/) over symbols, not expanded; matrices (GiNaC::matrix)
  /// compare entry by entry. Distinct symbols must have distinct names (the script names them).
  GiNaC::ex lhs, rhs;
};

/// Where a proof's files go: `dir` on disk (empty: write nothing) and `ref`, how claims.json names that folder
/// (e.g. "proofs/kaji.er.closed-form").
struct ProofFiles {
  std::filesystem::path dir;
  std::string ref;
};

/// Decides `identity` with both checkers and writes its files into `files.dir` (when set). The sentence's result
/// is "zero" (the identity holds) or "non-zero" (it fails: lhs − rhs is a nonzero rational function). Throws
/// std::runtime_error when the checkers disagree, std::invalid_argument on an expression neither can read.
claims::ProofSentence prove_identity(const Identity& identity, const ProofFiles& files);

}  // namespace affinterp::proofs
