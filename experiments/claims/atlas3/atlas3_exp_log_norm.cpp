#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/atlas3/cone_lemma.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/citations.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3::atlas3_exp_log_norm {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.exp-log.norm",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.2, Kaji §3",
    .statement = "The exp-log homotopy R^t S^t, A = RS, is good for norm exactly when S − I is semidefinite: the "
                 "eigenvalues l1, l2, l3 of S all ≥ 1 or all ≤ 1 (the 2D answer, generalised).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.2 for ‖R^t S^t v‖ = ‖S^t v‖ (Lemma L14).
// Method: Lemma L17 — in S's eigenbasis ‖S^t v‖² = Σ l_i^{2t} w_i, w_i = v_i² ≥ 0; its half-derivative
//   Σ w_i log(l_i) l_i^{2t} is non-decreasing, so a dip is a sign change from t = 0 to 1, and (Lemma L15) some w
//   makes one iff two axes i, j have g_i(0) > 0 > g_j(0) with log l_i log l_j (l_j² − l_i²) > 0; every sign
//   there is the sign of a polynomial in l (level C). Two quantifier-free sentences in l1, l2, l3.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::exp_log, proofs::Notion::norm);
  const proofs::Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L17 (exp-log in 3D): ||S^t v||^2 = sum l_i^(2t) w_i in S's eigenbasis; its half-derivative "
          "is non-decreasing, so it dips iff it changes sign from t = 0 to 1, iff (Lemma L15) two axes have "
          "slopes log l_i > 0 > log l_j with log l_i log l_j (l_j^2 - l_i^2) > 0; each sign is the sign of a "
          "polynomial in l (level C)",
      .sentences = atlas::condition_sentences(cell, "C", proofs::exp_log_norm_property(l)),
      .cites = std::string(proofs::citations::exponential),
      .formulations = {{.method = "level C with Lemma L15 (b) itself decided (sentence L15.cone); L17's monotone "
                                  "derivative and the exponential's monotonicity by hand",
                        .sentences =
                            with_cone_lemma(atlas::condition_sentences(cell, "C", proofs::exp_log_norm_property(l)))}},
      .attempts = {{.formulation = "3D Def 2.2.2 as written for R^t S^t",
                    .sentences = {},
                    .not_expressible = std::string(proofs::not_first_order_exponential)}},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(ctx, proofs::atlas3_cell(proofs::Homotopy::exp_log, proofs::Notion::norm), proof(),
                              {{"l1", "l2", 0, 3, {{"l3", Rational(1, 2)}}, "l3 = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_exp_log_norm
