#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/literal_formulations.hpp"

namespace affinterp::claims::atlas::atlas_svd_area {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.svd.area",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.1, thesis Thm 2.2.2 as corrected",
    .statement = "The SVD homotopy R_{tα}((1−t)I + tD)R_{tβ}, D = diag(x, y), x, y > 0, is good for area exactly "
                 "when 2xy ≤ x + y ≤ 2 or 2 ≤ x + y ≤ 2xy.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.1; det R_{tα} = det R_{tβ} = 1 (Lemma L5), so det A_s(t) = det((1−t)I + tD).
// Method: level E — monotone iff the derivative has one sign on [0, 1] (Lemma L1); it is affine, so its
//   signs at t = 0, 1 decide it, and positivity of a monotone f with f(0) = 1 is f(1) = det D > 0 (Lemma L2).
//   Two quantifier-free sentences in x, y.
// Second formulation: Def 2.2.1 as written (level L), Lemma L5 the only lemma.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::svd, proofs::Notion::area);
  const proofs::PolyMat2 D{{{Polynomial::variable("x"), Polynomial(0)}, {Polynomial(0), Polynomial::variable("y")}}};
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Def 2.2.1 for det((1-t)I + tD) (the rotations have determinant 1, Lemma L5) at level E: monotone iff "
          "the derivative keeps one sign on [0, 1] (Lemma L1), read at t = 0 and 1 because it is affine, with "
          "positivity from det > 0 at t = 1 (Lemma L2)",
      .sentences = condition_sentences(cell, "E", proofs::area_property(D, "E")),
      .z3_only = {},
      .identities = {},
      .cites = {},
      .formulations = {proofs::area_literal({"", cell.variables, cell.domain, cell.condition_formula(), D})},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::svd, proofs::Notion::area), proof(),
                       {{"x", "y", 0, 4, {}, "the (x, y) plane"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_svd_area
