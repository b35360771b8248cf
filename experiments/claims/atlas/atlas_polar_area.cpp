#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/literal_formulations.hpp"

namespace affinterp::claims::atlas::atlas_polar_area {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.polar.area",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.1, thesis Thm 2.2.4 as corrected",
    .statement = "The polar homotopy R_{tθ}((1−t)I + tS), S = [[x, h], [h, y]] positive definite, is good for area "
                 "exactly when 2 det S ≤ tr S ≤ 2 or 2 ≤ tr S ≤ 2 det S.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.1; det R_{tθ} = 1 (Lemma L5), so det A_p(t) = det((1−t)I + tS).
// Method: level E (Lemmas L1, L2, as for atlas.linear.area). Two quantifier-free sentences in x, y, h.
// Second formulation: Def 2.2.1 as written (level L), Lemma L5 the only lemma.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::polar, proofs::Notion::area);
  const Polynomial h = Polynomial::variable("h");
  const proofs::PolyMat2 S{{{Polynomial::variable("x"), h}, {h, Polynomial::variable("y")}}};
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Def 2.2.1 for det((1-t)I + tS) (the rotation has determinant 1, Lemma L5) at level E: monotone iff "
          "the derivative keeps one sign on [0, 1] (Lemma L1), read at t = 0 and 1 because it is affine, with "
          "positivity from det > 0 at t = 1 (Lemma L2)",
      .sentences = condition_sentences(cell, "E", proofs::area_property(S, "E")),
      .z3_only = {},
      .identities = {},
      .cites = {},
      .formulations = {proofs::area_literal({"", cell.variables, cell.domain, cell.condition_formula(), S})},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::polar, proofs::Notion::area), proof(),
                       {{"x", "y", 0, 4, {{"h", Rational(1, 2)}}, "h = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_polar_area
