#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/literal_formulations.hpp"

namespace affinterp::claims::atlas::atlas_linear_area {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.linear.area",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.1, thesis Thm 2.2.1 as corrected",
    .statement = "The linear homotopy (1−t)I + tA, det A > 0, is good for area exactly when 2 det A ≤ tr A ≤ 2 or "
                 "2 ≤ tr A ≤ 2 det A.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.1 for det A(t) = det((1−t)I + tA), a quadratic in t with value 1 at t = 0.
// Method: level E — monotone on [0, 1] iff the derivative has one sign there (Lemma L1); the derivative is
//   affine, so its signs at t = 0, 1 (tr A − 2 and 2 det A − tr A) decide it, and positivity on [0, 1] of a
//   monotone f with f(0) = 1 is f(1) = det A > 0 (Lemma L2). Two sentences in a, b, c, d.
// Second formulation: Def 2.2.1 as written (level L), no lemma; QEPCAD with Hong's projection (its
//   default, McCallum's, errs on these sentences in a, b, c, d).
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::linear, proofs::Notion::area);
  const proofs::PolyMat2 A{
      {{Polynomial::variable("a"), Polynomial::variable("b")}, {Polynomial::variable("c"), Polynomial::variable("d")}}};
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Def 2.2.1 for det((1-t)I + tA) at level E: monotone iff the derivative keeps one sign on [0, 1] "
          "(Lemma L1), read at t = 0 and 1 because it is affine, with positivity from det A > 0 (Lemma L2)",
      .sentences = condition_sentences(cell, "E", proofs::area_property(A, "E")),
      .z3_only = {},
      .identities = {},
      .cites = {},
      .formulations = {proofs::area_literal({"", cell.variables, cell.domain, cell.condition_formula(), A, true})},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::linear, proofs::Notion::area), proof(),
                       {{"a", "d", -1, 4, {{"b", 0}, {"c", Rational(1, 2)}}, "b = 0, c = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_linear_area
