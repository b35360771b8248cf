#include "experiments/claims/atlas3/singular_values.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/citations.hpp"

namespace affinterp::claims::atlas3::atlas3_exp_log_singular_values {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.exp-log.singular-values",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (Kaji et al.'s finer evaluators, in 3D)",
    .statement = "The exp-log homotopy R^t S^t is good for singular values for every A ∈ GL⁺(3): each sorted singular "
                 "value of A(t) "
                 "is l_(k)^t = e^{t log l_(k)}, monotone on [0, 1].",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: A(t) is good for singular values when σ1(t) ≥ σ2(t) ≥ σ3(t) are each monotone on [0, 1] (L25).
// Method: Lemma L25 — the rotations do not change singular values, those of the remaining symmetric positive
//   definite factor are its eigenvalues, and these keep their order on (0, 1]; the residue sentences say so.
// Sizes: the sentences are the same at every size; the suite has no decider to compare (nothing is left to evaluate).

atlas::AtlasProof proof() {
  const proofs::AtlasCell& cell = singular_values_cell(proofs::Homotopy::exp_log);
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L25: the sorted singular values of A(t) are l_(k)^t = e^{t log l_(k)}, each monotone; the residue "
          "sentences "
          "(positivity and order on (0, 1]) are empty",
      .sentences = exponent_order_sentences(),
      .cites = std::string(proofs::citations::exponential),
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(ctx, singular_values_cell(proofs::Homotopy::exp_log), proof(),
                              {{"l1", "l2", 0, 3, {{"l3", Rational(1, 2)}}, "l3 = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_exp_log_singular_values
