// The value of the global error function at a frame (theory/global/frame_energy.hpp): the closed forms of
// the local errors agree with the quadratic form the engine minimises, the parts add up, and the solved
// frame is the minimum.
#include "checks/global/strip.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>

#include <random>

namespace affinterp::global::frame_energy_test {
namespace {

/// vᵀGv + vᵀu + c of the frame's dense form (Kaji Appendix), at the vertices `v`.
double quadratic_value(const FrameQuadratic& q, const Eigen::Matrix2Xd& v) {
  const Eigen::Map<const Eigen::VectorXd> x(v.data(), v.size());
  return x.dot(q.G * x) + x.dot(q.u) + q.c;
}

Eigen::Matrix2Xd jiggled(const Eigen::Matrix2Xd& v, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-size, size);
  Eigen::Matrix2Xd moved = v;
  for (Eigen::Index k = 0; k < v.size(); ++k) moved.data()[k] += uniform(rng);
  return moved;
}

TEST(FrameEnergy, IsTheMinimisedFormAndItsPartsAddUp) {
  const Mesh P = testing::strip(6, 1), Q = testing::bent(P, 3.0);  // radius 2 > 1 row
  for (const Energy energy : {Energy::F, Energy::S, Energy::R, Energy::blend})
    for (const bool symmetric : {false, true})
      for (const bool area : {false, true}) {
        SCOPED_TRACE(to_string(energy) + (symmetric ? " symmetric" : "") + (area ? " area" : ""));
        InterpolationOptions options;
        options.energy = energy, options.symmetric = symmetric, options.area_weighted = area;
        options.blend_weight = 0.3;
        options.constraints.edges.push_back({0, 1, EdgeDirection::Path::local_homotopy, 1.0});
        options.constraints.barycentre = BarycentreLocus{};
        options.t_begin = -0.5, options.t_end = 1.5;
        const Interpolation interpolation(P, Q, options);
        for (const double t : {-0.5, 0.0, 0.3, 1.0, 1.5}) {
          const Eigen::Matrix2Xd v = interpolation.vertices_at(t);
          const FrameEnergy e = interpolation.energy_at(t, v);
          const FrameQuadratic q = interpolation.quadratic_at(t);
          const double scale = 1 + std::abs(q.c);
          EXPECT_NEAR(e.total, quadratic_value(q, v), 1e-9 * scale);
          EXPECT_NEAR(e.total, e.forward + e.backward + e.constraints, 1e-12 * scale);
          EXPECT_NEAR(e.forward + e.backward, e.frobenius + e.similarity, 1e-12 * scale);
          if (!symmetric) {
            EXPECT_EQ(e.backward, 0.0);
          }
          if (energy == Energy::F) {
            EXPECT_EQ(e.similarity, 0.0);
          }
          if (energy == Energy::R || energy == Energy::S) {
            EXPECT_EQ(e.frobenius, 0.0);
          }
          for (unsigned seed = 1; seed <= 3; ++seed) {
            const Eigen::Matrix2Xd other = jiggled(v, 0.1, seed);
            const double value = interpolation.energy_at(t, other).total;
            EXPECT_NEAR(value, quadratic_value(q, other), 1e-9 * scale);  // off the minimiser too
            EXPECT_GT(value, e.total);                                    // and the frame is the minimum
          }
        }
      }
}

TEST(FrameEnergy, RefusesAFrameOfAnotherMesh) {
  const Mesh P = testing::strip(2, 1), Q = testing::bent(P, 1.0);
  InterpolationOptions options;
  options.energy = Energy::F;
  options.constraints.barycentre = BarycentreLocus{};
  const Interpolation interpolation(P, Q, options);
  EXPECT_THROW(interpolation.energy_at(0.5, Eigen::Matrix2Xd::Zero(2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace affinterp::global::frame_energy_test
