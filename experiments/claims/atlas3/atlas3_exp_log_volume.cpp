#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/citations.hpp"

namespace affinterp::claims::atlas3::atlas3_exp_log_volume {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.exp-log.volume",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.1, Kaji §3",
    .statement = "The exp-log homotopy R^t S^t, A = RS, is good for volume for every A ∈ GL⁺(3).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.1 for det R^t S^t = det S^t (det R^t = 1, Lemma L14).
// Method: Lemma L17 — S^t = Q diag(l_i^t) Qᵀ, so det A(t) = (l1 l2 l3)^t = exp(t log det S): positive with a
//   derivative of one sign whenever det S > 0. The algebraic residue is one sentence (a point of the domain with
//   l1 l2 l3 <= 0); "condition false, property true" is empty because the condition is `true`.
// Sizes: the sentence is the same at every size; the suite has no exact decider for this cell (nothing to
//   evaluate: L17 is the whole argument).

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::exp_log, proofs::Notion::volume);
  const Polynomial det = Polynomial::variable("l1") * Polynomial::variable("l2") * Polynomial::variable("l3");
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L17 (exp-log in 3D): det A(t) = (l1 l2 l3)^t = exp(t log det S), positive with a derivative "
          "of one sign, so good for volume iff det S > 0; the residue sentence (l1 l2 l3 <= 0 on the domain) "
          "is empty, and condition-false-property-true is empty because the condition is true",
      .sentences = {atlas::atlas_sentence(cell, "cond-not-prop.residue",
                                          "eigenvalues l1, l2, l3 > 0 with l1 l2 l3 <= 0 (where L17's reduced "
                                          "property fails)",
                                          !logic::greater(det, 0))},
      .cites = std::string(proofs::citations::exponential),
      .attempts = {{.formulation = "3D Def 2.2.1 as written for R^t S^t",
                    .sentences = {},
                    .not_expressible = std::string(proofs::not_first_order_exponential)}},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(ctx, proofs::atlas3_cell(proofs::Homotopy::exp_log, proofs::Notion::volume), proof(),
                              {{"l1", "l2", 0, 3, {{"l3", Rational(1, 2)}}, "l3 = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_exp_log_volume
