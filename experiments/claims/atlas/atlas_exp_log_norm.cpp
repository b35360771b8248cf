#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/citations.hpp"

namespace affinterp::claims::atlas::atlas_exp_log_norm {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.exp-log.norm",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.2, Kaji §3",
    .statement = "The exp-log homotopy R_{tθ} S^t, S = [[x, h], [h, y]] positive definite, is good for norm exactly "
                 "when (x − 1)(y − 1) ≥ h², i.e. both eigenvalues of S lie on the same side of 1.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.2 for ‖R_{tθ} S^t v‖ = ‖S^t v‖ (R_{tθ} orthogonal).
// Method: Lemma L10 — with w = Qᵀv, ‖S^t v‖² = λ1^{2t} w1² + λ2^{2t} w2²: if both log λi have one sign every
//   derivative does; if λ1 > 1 > λ2 the scaled derivative l1 e^{2(l1−l2)t} w1² + l2 w2² is increasing and some
//   w makes it change sign on [0, 1]. So good for norm iff (λ1 − 1)(λ2 − 1) ≥ 0. Two sentences with the
//   eigenvalues as variables (λ1 + λ2 = tr S, λ1λ2 = det S, λi > 0; they exist by the spectral theorem, L13).
// Sizes: the sentences are the same at every size; the suite has no exact decider for this cell.

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::exp_log, proofs::Notion::norm);
  const Polynomial l1 = Polynomial::variable("l1"), l2 = Polynomial::variable("l2");
  const logic::Formula eigenvalues = logic::greater(l1, 0) && logic::greater(l2, 0) &&
                                     logic::equal(l1 + l2, cell.macros.at("tr")) &&
                                     logic::equal(l1 * l2, cell.macros.at("det"));
  const logic::Formula property = logic::greater_equal((l1 - Polynomial(1)) * (l2 - Polynomial(1)), 0);
  const logic::Formula condition = cell.condition_formula();
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L10 (exp-log): ||S^t v||^2 = l1^(2t) w1^2 + l2^(2t) w2^2 (w = Q^T v) is monotone for every v "
          "iff the eigenvalues l1, l2 of S lie on one side of 1, i.e. (l1 - 1)(l2 - 1) >= 0; the sentences "
          "carry l1, l2 as variables with l1 + l2 = tr S, l1 l2 = det S (spectral theorem, L13)",
      .sentences = {atlas_sentence(cell, "cond-not-prop.eig",
                                   "S with eigenvalues l1, l2 where the condition holds and (l1 - 1)(l2 - 1) < 0",
                                   eigenvalues && condition && !property, {"l1", "l2"}),
                    atlas_sentence(cell, "prop-not-cond.eig",
                                   "S with eigenvalues l1, l2 where (l1 - 1)(l2 - 1) >= 0 and the condition fails",
                                   eigenvalues && !condition && property, {"l1", "l2"})},
      .z3_only = {},
      .identities = {},
      .cites = std::string(proofs::citations::exponential),
      .formulations = {},
      .attempts = {{.formulation = "Def 2.2.2 as written for R_{t theta} S^t",
                    .sentences = {},
                    .not_expressible = std::string(proofs::not_first_order_exponential)}},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::exp_log, proofs::Notion::norm), proof(),
                       {{"x", "y", 0, 4, {{"h", Rational(1, 2)}}, "h = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_exp_log_norm
