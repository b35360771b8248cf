#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/atlas3/cone_lemma.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3::atlas3_polar_norm {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.polar.norm",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.2",
    .statement = "The polar homotopy R^t((1−t)I + tS), A = RS, is good for norm exactly when S − I is semidefinite: "
                 "the eigenvalues l1, l2, l3 of S all ≥ 1 or all ≤ 1 (the 2D answer, generalised).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.2; R^t is orthogonal (Lemma L14), so ‖A(t)v‖ = ‖((1−t)I + tS)v‖, and in S's eigenbasis
//   S = diag(l1, l2, l3) (Lemma L15).
// Method: level E — the squared norm's derivative is affine in t with slope ≥ 0 (L3, any dimension), so it is
//   monotone for v iff the derivative does not change strict sign from t = 0 to t = 1; for all v ∈ ℝ³ (v = 0 is
//   monotone, L6). Two sentences in l1, l2, l3 with v1, v2, v3 quantified. Second formulation: level C (Lemma
//   L15's cone of per-axis slopes), quantifier-free in l1, l2, l3.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::polar, proofs::Notion::norm);
  const proofs::Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  // McCallum's projection warns that a projection factor vanishes on a cylinder (the forms in v are homogeneous):
  // Hong's projection is complete.
  std::vector<proofs::Sentence> level_E = atlas::condition_sentences(cell, "E", proofs::polar_norm_property(l));
  for (proofs::Sentence& s : level_E) s.qepcad_setup = proofs::hong_projection(s.formula);
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "3D Def 2.2.2 for ((1-t)I + tS)v (the rotation is orthogonal, Lemma L14) in S's eigenbasis "
          "(Lemma L15) at level E: the squared norm's t-derivative is affine with slope >= 0 (L3), so it is "
          "monotone for v unless its derivative is < 0 at t = 0 and > 0 at t = 1; for every v in R^3",
      .sentences = level_E,
      .formulations = {{.method = "level C: the cone of the per-axis slopes (mu_i, mu_i l_i), mu_i = l_i - 1, "
                                  "meets no open second quadrant (Lemma L15, Caratheodory in the plane)",
                        .sentences = atlas::condition_sentences(cell, "C", proofs::polar_norm_cone_property(l))},
                       {.method = "level C with Lemma L15 (b) itself decided (sentence L15.cone): no step by hand "
                                  "but the eigenbasis (L15 (a)) and L3",
                        .sentences = with_cone_lemma(
                            atlas::condition_sentences(cell, "C", proofs::polar_norm_cone_property(l)))}},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(
      ctx, proofs::atlas3_cell(proofs::Homotopy::polar, proofs::Notion::norm), proof(),
      {{"l1", "l2", 0, 3, {{"l3", Rational(1, 2)}}, "l3 = 1/2"}, {"l1", "l2", 0, 3, {{"l3", Rational(2)}}, "l3 = 2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_polar_norm
