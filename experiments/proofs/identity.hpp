#pragma once
// Polynomial and rational identities as parts of a proof: lhs = rhs for all values of the symbols
// where both sides are defined, decided by two independent checkers,
//   ginac       GiNaC performs the steps (diff, subs, evalm, determinant) on a copy, and normal() of lhs − rhs is
//               0 (polynomial arithmetic and gcd cancellation), and
//   exact-grid  exact integer evaluation of the unexpanded sides on a grid large enough for their degree, with the
//               steps performed by its own arithmetic (exact_grid.hpp), which shares no arithmetic with GiNaC.
// An identity carries its step: a derivative, substitution, matrix product, transpose or determinant is a node of
// the sides (step_nodes.hpp), not done while the sides are built, so each checker performs it.
// Both read the sides back from the text of a ginsh script, <name>.ginsh, written first: one line
// `is(normal((lhs) - (rhs)) == 0);` per entry, the steps written as ginsh's commands, which `ginsh <name>.ginsh`
// performs and answers with 1 (holds) or 0, so anyone can rerun it with GiNaC's own shell; <name>.ginsh.out holds
// those answers and <name>.grid.out the grid checker's bounds and result.
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/proof.hpp"

#include <ginac/ginac.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::proofs {

struct Identity {
  std::string name;     ///< the file stem, e.g. "complete-square"
  std::string meaning;  ///< one line: what lhs = rhs says, in words
  /// Both sides built from the suite's own algebra (theory/) over symbols, not expanded, with their steps as step
  /// nodes; matrices (GiNaC::matrix, or a product or transpose node) compare entry by entry. Distinct symbols must
  /// have distinct names (the script names them).
  GiNaC::ex lhs, rhs;
};

/// Decides `identity` with both checkers and writes its files into `files.dir` (when set). The sentence's result
/// is "zero" (the identity holds) or "non-zero" (it fails: lhs − rhs is a nonzero rational function). Throws
/// std::runtime_error when the checkers disagree, std::invalid_argument on an expression neither can read.
ProofSentence prove_identity(const Identity& identity, const SentenceFiles& files);

/// prove_identity of each, in order.
std::vector<ProofSentence> prove_identities(const std::vector<Identity>& identities, const SentenceFiles& files);

/// A proof of identities alone (make_proof: checked by GiNaC and the exact grid when both answered).
Proof identity_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences);

/// A proof of identities (checked by GiNaC and the exact grid) and first-order sentences (checked by the deciders
/// that decided every one), identities first; checked_by computed by make_proof.
Proof combined_proof(std::string scope, std::string method, std::vector<ProofSentence> identities,
                     std::vector<ProofSentence> sentences);

/// Whether `proof` proves its claim as stated: decided (by one checker at least; claims::proof_strength says how
/// strongly), not structural alone, every identity "zero" and every sentence "empty".
bool proves(const Proof& proof);

/// Whether some part of `proof` was decided against the claim: an identity "non-zero" or a sentence "non-empty".
bool contradicted(const Proof& proof);

}  // namespace affinterp::proofs
