#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/random_gl_plus.hpp"
#include "theory/local/local.hpp"

#include <algorithm>

namespace affinterp::claims::local {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.exp.endpoints",
    .chapter = Chapter::local,
    .where = "Kaji eq. (3)",
    .statement = "The exp-log homotopy R_θ^t S^t equals I at t = 0 and A at t = 1.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: θ is any representative of the polar angle (Kaji §4 shifts it by 2πk), so the endpoints must hold
//   for every k.
// Method: A^E(t) = R_{tθ} S^t (Kaji eq. (3)) evaluated in Real50 at t = 0 and 1 on random A ∈ GL+(2), θ shifted
//   by 2πk, |k| ≤ 2; the worst of |A^E(0) − I| and the relative |A^E(1) − A| must stay below 1e-40.
// Sizes: quick 100 matrices; full 2000.

using affinterp::local::ExpLogHomotopy;

Real50 relative_gap(const Mat2<Real50>& got, const Mat2<Real50>& want) { return (got - want).norm() / want.norm(); }

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const int samples = ctx.pick(100, 2000);
  Real50 worst = 0;
  for (int i = 0; i < samples; ++i) {
    const Mat2<Real50> A = random_gl_plus(rng, 1e3);
    const auto polar = affinterp::local::polar_decomposition(A);
    const int k = static_cast<int>(rng.integer(-2, 2));  // any representative θ + 2πk (Kaji §4)
    // Kaji eq. (3): A^E(t) = R_{tθ} S^t.
    const ExpLogHomotopy<Real50> A_E(polar.theta + 2 * k * affinterp::local::pi<Real50>(), polar.S);
    worst = std::max({worst, Real50((A_E(Real50(0)) - affinterp::local::identity2<Real50>()).norm()),
                      relative_gap(A_E(Real50(1)), A)});
  }
  Outcome outcome;
  outcome.evidence.method = "Real50 evaluation of A^E(t) = R_{t theta} S^t at t = 0 and 1";
  outcome.evidence.sample_size = static_cast<std::uint64_t>(samples);
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.tolerance = 1e-40;
  outcome.evidence.worst_deviation = static_cast<double>(worst);
  outcome.evidence.details = {
      {"sample", "A = R_alpha diag(x, y) R_beta, x/y <= 1e3, det A in [1/16, 16], theta shifted by 2 pi k, |k| <= 2"},
      {"measure", "max(|A^E(0) - I|_F, |A^E(1) - A|_F / |A|_F)"}};
  const bool holds = worst < Real50("1e-40");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = holds ? "A^E(0) = I and A^E(1) = A on " + std::to_string(samples) +
                                " random A (Real50, any representative of theta)"
                          : "A^E misses an endpoint";
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local
