#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/citations.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/literal_formulations.hpp"

namespace affinterp::claims::atlas::atlas_polar_norm {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.polar.norm",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.2, thesis Thm 2.2.5",
    .statement = "The polar homotopy R_{tθ}((1−t)I + tS), S = [[x, h], [h, y]] positive definite, is good for norm "
                 "exactly when (x − 1)(y − 1) ≥ h², i.e. det(S − I) ≥ 0 (Thm 2.2.5's second conjunct is implied).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.2; R_{tθ} is orthogonal (Lemma L5), so ‖A_p(t)v‖ = ‖((1−t)I + tS)v‖.
// Method: level N — ‖·‖ monotone iff its square is (L4); with M = S − I, ½ d/dt‖(I + tM)v‖² = P(v) + t‖Mv‖²,
//   affine with non-negative slope, so monotone for v iff ¬(P(v) < 0 < Q(v)), P = sym M, Q = P + MᵀM (L3),
//   for all v iff for all v ≠ 0 (L6), iff Q ⪯ 0 or ∃ν ≥ 0: P − νQ ⪰ 0 (Dines, L8). Two sentences in x, y, h
//   with ν quantified. Second formulations without Dines' theorem: the directions (1, m), (0, 1) at
//   levels D and E, each lemma a sentence; level L is tried for the record under thesis.thm-2.2.5.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::polar, proofs::Notion::norm);
  const Polynomial h = Polynomial::variable("h");
  const proofs::PolyMat2 S{{{Polynomial::variable("x"), h}, {h, Polynomial::variable("y")}}};
  const proofs::ConditionOnDomain literal{"", cell.variables, cell.domain, cell.condition_formula(), S};
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Def 2.2.2 for ((1-t)I + tS)v (the rotation is orthogonal, Lemma L5) at level N: the squared norm "
          "(L4) has an affine t-derivative with non-negative slope, so it is monotone for v unless "
          "P(v) < 0 < Q(v), P = sym(S - I), Q = P + (S - I)^2 (L3); homogeneous in v (L6); no such v iff "
          "Q <= 0 or P - nu Q >= 0 for some nu >= 0 (Dines 1941, L8)",
      .sentences = condition_sentences(cell, "N", proofs::norm_property(S, "N")),
      .z3_only = {},
      .identities = {},
      .cites = std::string(proofs::citations::dines),
      .formulations = proofs::norm_directions(literal),
      .attempts = {},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::polar, proofs::Notion::norm), proof(),
                       {{"x", "y", 0, 4, {{"h", Rational(1, 2)}}, "h = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_polar_norm
