#include "theory/origin/frame_interpolation.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/symbols.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checks/origin/rational_gen.hpp"

#include <Eigen/LU>

#include <cmath>

namespace frame_interpolation_test {

using namespace affinterp::origin;

namespace {

/// An affine map with positive determinant from small integers (a grid, so every case is exact input).
Eigen::Matrix3d affine(int a, int b, int c, int d, int e, int f) {
  Eigen::Matrix3d A;
  A << a, b, e, c, d, f, 0, 0, 1;
  return A;
}

}  // namespace

RC_GTEST_PROP(LocalInterpolation, RunsFromTheIdentityToA, (int a, int b, int c, int d, int e, int f, int ox, int oy)) {
  const Eigen::Matrix3d A = affine(a % 7, b % 7, c % 7, d % 7, e % 7, f % 7);
  RC_PRE((A.topLeftCorner<2, 2>().determinant() > 0));
  const Eigen::Vector2d o(ox % 5, oy % 5);
  RC_ASSERT((local_interpolation(A, o, 0) - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  RC_ASSERT((local_interpolation(A, o, 1) - A).norm() < 1e-12 * (1 + A.norm()));
}

RC_GTEST_PROP(LocalInterpolation, MovesTheOriginOfItsFrameOnAStraightLine,
              (int a, int b, int c, int d, int e, int f, int ox, int oy)) {
  // In the frame with origin o the translation is interpolated linearly: A(t) o = o + t (A o − o).
  const Eigen::Matrix3d A = affine(a % 7, b % 7, c % 7, d % 7, e % 7, f % 7);
  RC_PRE((A.topLeftCorner<2, 2>().determinant() > 0));
  const Eigen::Vector3d o(ox % 5, oy % 5, 1);
  for (const double t : {0.25, 0.5, 0.75})
    RC_ASSERT((local_interpolation(A, o.head<2>(), t) * o - (o + t * (A * o - o))).norm() < 1e-12 * (1 + A.norm()));
}

TEST(LocalInterpolation, RejectsAReflection) {
  EXPECT_THROW(local_interpolation(affine(-1, 0, 0, 1, 0, 0), Eigen::Vector2d::Zero(), 0.5), std::invalid_argument);
}

TEST(GlobalInterpolation, StartsAtTheSourceAndEndsAtTheExactMinimiser) {
  const TwoTriangles config = thesis_two_triangles();
  const OriginStudy study = study_origin(config);
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{0.5, -0.25}, std::pair{2.0, 1.5}}) {
    const std::array<Eigen::Vector2d, 2> origins{Eigen::Vector2d(x, y), Eigen::Vector2d(x, y)};
    const Eigen::Matrix<double, 2, 4> start = global_interpolation(config, origins, 0);
    const Eigen::Matrix<double, 2, 4> end = global_interpolation(config, origins, 1);
    const GiNaC::lst o{symbols().x == GiNaC::numeric(x), symbols().y == GiNaC::numeric(y)};
    for (unsigned k = 0; k < 4; ++k)
      for (unsigned r = 0; r < 2; ++r) {
        EXPECT_NEAR(start(r, k), GiNaC::ex_to<GiNaC::numeric>(config.source(r, k)).to_double(), 1e-12);
        const GiNaC::ex exact = symbols().v(r, k).subs(study.min_E2_common.minimiser).subs(o).evalf();
        EXPECT_NEAR(end(r, k), GiNaC::ex_to<GiNaC::numeric>(exact).to_double(), 1e-12) << "v" << k + 1;
      }
  }
}

}  // namespace frame_interpolation_test
