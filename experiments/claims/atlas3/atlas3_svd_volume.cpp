#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/atlas3/through_linear_volume.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3::atlas3_svd_volume {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.svd.volume",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.1",
    .statement = "The SVD homotopy U^t((1−t)I + tΣ)V^t, A = UΣVᵀ, is good for volume exactly when c1 + 2c2 t + 3c3 t² "
                 "keeps one sign on [0, 1], "
                 "c1, c2, c3 the elementary symmetric functions of l1 − 1, l2 − 1, l3 − 1 (the singular values l1, l2, "
                 "l3 of A): "
                 "the linear cell's condition for the invariants of S − I.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.1; U^t and V^t have determinant 1 (Lemma L14), so det A(t) = det((1−t)I + tΛ) = ∏(1 + t(l_i −
// 1)). Method: level D (Lemma L1) in l1, l2, l3 with t quantified: two sentences. Second formulation: through the
//   linear cell (Lemma L16; experiments/claims/atlas3/through_linear_volume.hpp).
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full).

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::svd, proofs::Notion::volume);
  const proofs::Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "3D Def 2.2.1 for det((1-t)I + t diag(l1, l2, l3)) = prod(1 + t(l_i - 1)) (the rotations have "
          "determinant 1, Lemma L14) at level D: positive on [0, 1] and the derivative of one sign there "
          "(Lemma L1)",
      .sentences = atlas::condition_sentences(
          cell, "D", proofs::volume_property(proofs::det_of_diagonal_blend(l, Polynomial::variable("t")))),
      .identities = {vieta_identity(cell)},
      .formulations = {through_linear_volume(cell)},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas::atlas_outcome(
      ctx, proofs::atlas3_cell(proofs::Homotopy::svd, proofs::Notion::volume), proof(),
      {{"l1", "l2", 0, 4, {{"l3", Rational(1, 4)}}, "l3 = 1/4"}, {"l1", "l2", 0, 4, {{"l3", Rational(3)}}, "l3 = 3"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_svd_volume
