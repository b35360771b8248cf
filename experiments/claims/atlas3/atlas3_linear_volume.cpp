#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3::atlas3_linear_volume {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.linear.volume",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.1",
    .statement = "The linear homotopy (1−t)I + tA of A ∈ GL⁺(3) is good for volume exactly when "
                 "c1 + 2c2 t + 3c3 t² keeps one sign on [0, 1], c1, c2, c3 = tr M, σ₂(M), det M of M = A − I.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.1 for det((1−t)I + tA) = det(I + tM).
// Method: Lemma L16 — det(I + tM) = 1 + c1 t + c2 t² + c3 t³ and every real (c1, c2, c3) is the invariants of
//   some M (its companion matrix), so the cell's parameters are exactly (c1, c2, c3) with 1 + c1 + c2 + c3 > 0;
//   level D (Lemma L1): positive on [0, 1] and the derivative of one sign. Two sentences in c1, c2, c3 with t
//   quantified.
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::linear, proofs::Notion::volume);
  const Polynomial p = proofs::det_by_invariants(Polynomial::variable("c1"), Polynomial::variable("c2"),
                                                 Polynomial::variable("c3"), Polynomial::variable("t"));
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "3D Def 2.2.1 for det(I + tM) = 1 + c1 t + c2 t^2 + c3 t^3 (Lemma L16; every real triple is "
          "realised by a companion matrix) at level D: positive on [0, 1] and the derivative of one sign "
          "there (Lemma L1)",
      .sentences = atlas::condition_sentences(cell, "D", proofs::volume_property(p)),
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(ctx, proofs::atlas3_cell(proofs::Homotopy::linear, proofs::Notion::volume), proof(),
                              {{"c1", "c2", -4, 4, {{"c3", Rational(0)}}, "c3 = 0"},
                               {"c1", "c2", -4, 4, {{"c3", Rational(1)}}, "c3 = 1"},
                               {"c1", "c2", -4, 4, {{"c3", Rational(-1, 2)}}, "c3 = -1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_linear_volume
