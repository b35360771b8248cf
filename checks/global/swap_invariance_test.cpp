// With default options the symmetrised interpolation does not depend on which mesh comes first: (P, Q) at t
// equals (Q, P) at 1 − t, frames and energy, for every local error (gauge.hpp), on random compatible pairs
// (experiments/inputs/shapes/random_pair.hpp: a random affine map with any rotation, plus per-vertex offsets).
#include "experiments/inputs/shapes/catalogue.hpp"
#include "theory/global/gauge.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numbers>

namespace affinterp::global::swap_invariance_test {
namespace {

/// The options `affinterp interpolate --symmetric` uses by default (area weights, the straight barycentre
/// locus, exp-log paths, consistent branches), with the default gauge of (source, target).
InterpolationOptions symmetric_defaults(Energy energy, double blend_weight, const Mesh& source, const Mesh& target) {
  InterpolationOptions options;
  options.energy = energy;
  options.blend_weight = blend_weight;
  options.area_weighted = true;
  options.symmetric = true;
  options.constraints.barycentre = BarycentreLocus{};
  options.t_begin = -0.5, options.t_end = 1.5;
  if (const auto edge = default_edge_direction(source, target, options)) options.constraints.edges.push_back(*edge);
  return options;
}

double diameter(const Mesh& P, const Mesh& Q) {
  const Eigen::Vector2d low = P.vertices.rowwise().minCoeff().cwiseMin(Q.vertices.rowwise().minCoeff());
  const Eigen::Vector2d high = P.vertices.rowwise().maxCoeff().cwiseMax(Q.vertices.rowwise().maxCoeff());
  return (high - low).norm();
}

RC_GTEST_PROP(SwapInvariance, SymmetrisedFramesDoNotDependOnWhichMeshComesFirst, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(1, 1000000);
  const auto [P, Q] = shapes::random_pair(seed, *rc::gen::inRange(3, 40));
  const Energy energy = *rc::gen::element(Energy::F, Energy::S, Energy::R, Energy::blend);
  const double w = *rc::gen::inRange(0, 11) / 10.0, t = *rc::gen::inRange(-5, 16) / 10.0;
  RC_TAG(to_string(energy));
  const InterpolationOptions forward = symmetric_defaults(energy, w, P, Q),
                             reverse = symmetric_defaults(energy, w, Q, P);
  RC_ASSERT(forward.constraints.edges.size() == reverse.constraints.edges.size());
  if (!forward.constraints.edges.empty()) {  // the same edge, whichever way round
    const EdgeDirection &a = forward.constraints.edges[0], &b = reverse.constraints.edges[0];
    RC_ASSERT(std::minmax(a.i, a.j) == std::minmax(b.i, b.j));
  }
  const Interpolation PQ(P, Q, forward), QP(Q, P, reverse);
  // the reverse problem's polar angles are −θ_i on the mirrored branches (A_i⁻¹ = R_{−θ} ·)
  RC_ASSERT((PQ.rotation_angles() + QP.rotation_angles()).cwiseAbs().maxCoeff() < 1e-12);
  const Eigen::Matrix2Xd v = PQ.vertices_at(t), v_swapped = QP.vertices_at(1 - t);
  const double gap = (v - v_swapped).colwise().norm().maxCoeff() / diameter(P, Q);
  RC_LOG() << "seed " << seed << ", max |v - v'| / diameter = " << gap << "\n";
  RC_ASSERT(gap < 1e-9);
  const FrameEnergy e = PQ.energy_at(t, v), e_swapped = QP.energy_at(1 - t, v_swapped);
  RC_ASSERT(std::abs(e.total - e_swapped.total) <= 1e-9 * std::max(1.0, e.total));
  // the two halves trade places: E(t) of (P, Q) is E^{-1}(1 − (1 − t)) of (Q, P)
  RC_ASSERT(std::abs(e.forward - e_swapped.backward) <= 1e-9 * std::max(1.0, e.total));
}

/// The worm turns its end by 3π: the consistent branches go beyond (−π, π], and the reverse run must take
/// the mirrored ones for E^F's paths R_{tθ} to match.
TEST(SwapInvariance, HoldsBeyondHalfATurn) {
  const auto [P, Q] = shapes::make_shape("worm-curl");
  for (const Energy energy : {Energy::F, Energy::R, Energy::blend}) {
    const Interpolation PQ(P, Q, symmetric_defaults(energy, 0.5, P, Q)),
        QP(Q, P, symmetric_defaults(energy, 0.5, Q, P));
    EXPECT_GT(PQ.rotation_angles().maxCoeff(), 2 * std::numbers::pi);
    EXPECT_LT((PQ.rotation_angles() + QP.rotation_angles()).cwiseAbs().maxCoeff(), 1e-12);
    for (const double t : {0.25, 0.5, 0.9})
      EXPECT_LT((PQ.vertices_at(t) - QP.vertices_at(1 - t)).colwise().norm().maxCoeff() / diameter(P, Q), 1e-9)
          << to_string(energy) << " t = " << t;
  }
}

}  // namespace
}  // namespace affinterp::global::swap_invariance_test
