#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/atlas3/through_linear_volume.hpp"
#include "experiments/claims/claim.hpp"

namespace affinterp::claims::atlas3::atlas3_polar_volume {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.polar.volume",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.1",
    .statement =
        "The polar homotopy R^t((1−t)I + tS), A = RS, is good for volume exactly when c1 + 2c2 t + 3c3 t² keeps one "
        "sign on [0, 1], "
        "c1, c2, c3 the elementary symmetric functions of l1 − 1, l2 − 1, l3 − 1 (the eigenvalues l1, l2, l3 of S): "
        "the linear cell's condition for the invariants of S − I.",
    .strength = Strength::sample,
    .check = check,
}};

Outcome check(const ClaimContext& ctx) { return eigenvalue_volume_outcome(ctx, proofs::Homotopy::polar); }

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_polar_volume
