#include "experiments/claims/atlas3/singular_values.hpp"
#include "experiments/claims/claim.hpp"

namespace affinterp::claims::atlas3::atlas3_polar_singular_values {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.polar.singular-values",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (Kaji et al.'s finer evaluators, in 3D)",
    .statement = "The polar homotopy R^t((1−t)I + tS) is good for singular values for every A ∈ GL⁺(3): each sorted "
                 "singular value of A(t) "
                 "is 1 + t(l_(k) − 1), monotone on [0, 1].",
    .strength = Strength::sample,
    .check = check,
}};

Outcome check(const ClaimContext& ctx) { return blend_singular_values_outcome(ctx, proofs::Homotopy::polar); }

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_polar_singular_values
