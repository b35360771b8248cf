// The test-matrix families of the accuracy sweep (experiments/inputs/sym3/families.hpp): deterministic for a
// seed, symmetric, with the spectra they promise.
#include "experiments/inputs/sym3/families.hpp"

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace affinterp::sym3::families_test {
namespace {

TEST(Families, AreDeterministicAndSymmetric) {
  for (const Family& family : families()) {
    const auto a = family.draw(family, 7, 20), b = family.draw(family, 7, 20);
    ASSERT_EQ(a.size(), 20u) << family.name;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i], b[i]) << family.name;
      EXPECT_EQ(a[i], a[i].transpose()) << family.name;
    }
  }
}

TEST(Families, HaveThePromisedSpectra) {
  for (const Family& family : families()) {
    for (const Mat3& S : family.draw(family, 11, 50)) {
      Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(S, Eigen::EigenvaluesOnly).eigenvalues();
      const double slack = 1e-14 * std::max(1.0, S.norm());
      if (family.in_thesis_range) {
        EXPECT_GE(lambda.minCoeff(), -slack) << family.name;
        EXPECT_LE(lambda.maxCoeff(), 3 + slack) << family.name;
      }
      if (family.gap && *family.gap >= 1e-6) {
        // The clustered eigenvalues keep their gap up to rounding.
        double best = INFINITY;
        for (int i = 0; i < 3; ++i)
          for (int j = i + 1; j < 3; ++j)
            best = std::min(best, std::abs(std::abs(lambda[i] - lambda[j]) - *family.gap));
        EXPECT_LT(best, 1e-3 * *family.gap + slack) << family.name;
      }
    }
  }
}

TEST(Families, ThesisDistributionIsPositiveSemidefinite) {
  for (const Mat3& S : thesis_distribution(3, 200)) {
    const Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(S, Eigen::EigenvaluesOnly).eigenvalues();
    EXPECT_GE(lambda.minCoeff(), -1e-14);
    EXPECT_LE(lambda.maxCoeff(), 9 + 1e-12);
  }
}

}  // namespace
}  // namespace affinterp::sym3::families_test
