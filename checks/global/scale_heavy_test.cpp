// The engine's scale case at full size: a strip of 2000 × 250 quads (1,000,000 triangles, 18.8 × 2) rolled 1.5
// turns, which E^R refused before the barycentre was eliminated exactly (sparse_minimiser.hpp): every energy
// interpolates it with the options of `affinterp interpolate`, its barycentre on the straight locus.
// Label heavy: seconds per energy on 2 cores, 1–2 GB (`affinterp interpolate` on the same spiral: cli.spiral_1m).
#include "checks/global/strip.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>

namespace affinterp::global::scale_heavy_test {
namespace {

TEST(ScaleHeavy, MillionTriangleSpiralInterpolatesWithEveryEnergy) {
  const testing::Spiral s = testing::spiral(2000, 250);
  ASSERT_EQ(s.source.triangle_count(), 1'000'000);
  const double box = testing::box_size(s.source, s.target);
  const Eigen::Vector2d expected = (s.source.vertices.rowwise().mean() + s.target.vertices.rowwise().mean()) / 2;
  for (const Energy energy : {Energy::F, Energy::S, Energy::R, Energy::blend}) {
    const Interpolation interpolation(s.source, s.target, testing::cli_options(energy, s));
    const Eigen::Matrix2Xd v = interpolation.vertices_at(0.5);
    EXPECT_TRUE(v.allFinite()) << to_string(energy);
    EXPECT_LT((v.rowwise().mean() - expected).norm(), 1e-9 * box) << to_string(energy);
  }
}

}  // namespace
}  // namespace affinterp::global::scale_heavy_test
