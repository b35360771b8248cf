// The local theory in 3D (theory/local3): rotation logarithm and exponential at every angle, the branch helper,
// the rotation-only SVD, and the four homotopies' ends and exp-log's determinant.
#include "theory/local3/local3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>

namespace local3_test {

using namespace affinterp::local3;
using M = Mat3<double>;
using V = Vec3<double>;
constexpr double pi = std::numbers::pi;

/// A ∈ GL⁺(3) with entries uniform in [−2, 2], a column negated if det < 0.
M random_map(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  M A;
  do {
    for (int k = 0; k < 9; ++k) A(k) = u(rng);
  } while (std::abs(A.determinant()) < 0.05);
  if (A.determinant() < 0) A.col(0) = -A.col(0);
  return A;
}

V random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return V(g(rng), g(rng), g(rng)).normalized();
}

TEST(RotationExp, IsTheRotationAboutTheAxisByTheAngle) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 200; ++trial) {
    const V axis = random_unit(rng);
    const double theta = std::uniform_real_distribution<double>(0, 9)(rng);  // beyond 2π too
    const M R = rotation_exp<double>(theta * axis);
    EXPECT_LT((R - Eigen::AngleAxisd(theta, axis).toRotationMatrix()).norm(), 1e-14);
    EXPECT_LT((R * R.transpose() - M::Identity()).norm(), 1e-14);
  }
}

// log(exp ω) = ω for |ω| < π, to 4·10⁻¹⁶ relative at tiny angles and 10⁻¹⁴ absolute near π.
// The product through quaternions, its half-angles by the Taylor series (h ≤ 1/4) or the sine and cosine, against
// the two Rodrigues rotations multiplied in long double: within a few units in the last place, on both sides of
// the series' threshold |η| = 1/2 and at 0.
TEST(RotationExpProduct, IsTheProductOfTheTwoRotations) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  using VL = Vec3<long double>;
  for (const double a : {0.0, 1e-9, 0.1, 0.4999999, 0.5, 0.5000001, 1.0, 3.0, 7.0, 3 * pi})
    for (const double b : {0.0, 1e-9, 0.3, 0.4999999, 0.5, 0.5000001, 2.0, pi})
      for (int k = 0; k < 4; ++k) {
        const V u = V(normal(rng), normal(rng), normal(rng)).normalized(), w = V(normal(rng), normal(rng), normal(rng));
        const V omega = a * u, eta = b * w.normalized();
        const Mat3<long double> exact = rotation_exp<long double>(VL(omega.cast<long double>())) *
                                        rotation_exp<long double>(VL(eta.cast<long double>()));
        EXPECT_LT((rotation_exp_product<double>(omega, eta).cast<long double>() - exact).norm(), 4e-15L)
            << "|omega| = " << a << ", |eta| = " << b;
      }
}

TEST(RotationLog, RoundTripsOnThePrincipalBranch) {
  std::mt19937 rng(2);
  for (double theta : {1e-300, 1e-12, 1e-8, 1e-4, 0.5, 1.0, pi / 2, 2.0, 3.0, pi - 1e-6, pi - 1e-9, pi - 1e-13}) {
    for (int trial = 0; trial < 20; ++trial) {
      const V omega = theta * random_unit(rng);
      const V back = rotation_log<double>(rotation_exp<double>(omega));
      const double tolerance = theta < 1e-3 ? 4e-16 * theta : 1e-14;
      EXPECT_LE((back - omega).norm(), tolerance) << "theta " << theta;
    }
  }
}

// At θ = π both ±π·axis are principal logarithms: the log is one of them, and exp of it is R.
TEST(RotationLog, AnglePiTakesTheAxisFromTheSymmetricPart) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const V axis = random_unit(rng);
    const M R = Eigen::AngleAxisd(pi, axis).toRotationMatrix();
    const V omega = rotation_log<double>(R);
    EXPECT_NEAR(omega.norm(), pi, 1e-14);
    EXPECT_LT(std::min((omega - pi * axis).norm(), (omega + pi * axis).norm()), 1e-13);
    EXPECT_LT((rotation_exp<double>(omega) - R).norm(), 1e-14);
  }
  EXPECT_EQ(rotation_log<double>(M::Identity()), V::Zero());
}

TEST(NearestLog, IsTheNearestRepresentativeOfTheSameRotation) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-15, 15);
  for (int trial = 0; trial < 200; ++trial) {
    const V omega = std::uniform_real_distribution<double>(0.01, pi)(rng) * random_unit(rng);
    const V reference(u(rng), u(rng), u(rng));
    const V chosen = nearest_log<double>(omega, reference);
    EXPECT_LT((rotation_exp<double>(chosen) - rotation_exp<double>(omega)).norm(), 1e-13);
    const V axis = omega.normalized();
    for (int k = -6; k <= 6; ++k)  // every representative (θ + 2πk) a, k = −1 … the turn the other way
      EXPECT_LE((chosen - reference).norm(), ((omega.norm() + 2 * pi * k) * axis - reference).norm() + 1e-12);
  }
  EXPECT_LT((nearest_log<double>(V(0, 0, 1), V(0, 0, 7)) - V(0, 0, 1 + 2 * pi)).norm(), 1e-15);
  EXPECT_LT((nearest_log<double>(V(0, 0, 1), V(0, 0, -4)) - V(0, 0, 1 - 2 * pi)).norm(), 1e-15);
  EXPECT_LT((nearest_log<double>(V::Zero(), V(0, 13, 0)) - V(0, 4 * pi, 0)).norm(), 1e-14);
  EXPECT_EQ(nearest_log<double>(V::Zero(), V(1, 0, 0)), V::Zero());
}

TEST(Svd3, HasRotationsAndPositiveDescendingSingularValues) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const M A = random_map(rng);
    const Svd3<double> d = svd3<double>(A);
    EXPECT_NEAR(d.U.determinant(), 1, 1e-14);
    EXPECT_NEAR(d.V.determinant(), 1, 1e-14);
    EXPECT_GT(d.sigma[2], 0);
    EXPECT_GE(d.sigma[0], d.sigma[1]);
    EXPECT_GE(d.sigma[1], d.sigma[2]);
    EXPECT_LT((d.matrix() - A).norm(), 1e-14 * A.norm());
    const Polar3<double> polar = polar3(d);
    EXPECT_LT((polar.R * polar.S - A).norm(), 1e-14 * A.norm());
  }
  EXPECT_THROW(svd3<double>(M(Eigen::Vector3d(1, 1, -1).asDiagonal())), std::invalid_argument);
  EXPECT_THROW(svd3<double>(M::Zero()), std::invalid_argument);
}

// Procrustes: R maximises tr(Rᵀ M) over SO(3), checked against random rotations, for full-rank M of either sign
// and for the rank-2 products a triangle's in-plane map gives; M = R₀ S (S SPD) gives R₀, its polar factor.
TEST(NearestRotation, MaximisesTheTraceAgainstEveryOtherRotation) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, pi);
  for (int trial = 0; trial < 60; ++trial) {
    M Mat = random_map(rng);
    if (trial % 3 == 1) Mat.col(0) = -Mat.col(0);                               // det M < 0
    if (trial % 3 == 2) Mat = Mat * V(1, 1, 0).asDiagonal() * random_map(rng);  // rank 2
    const M R = nearest_rotation<double>(Mat);
    EXPECT_LT((R.transpose() * R - M::Identity()).norm(), 1e-14);
    EXPECT_NEAR(R.determinant(), 1, 1e-14);
    for (int other = 0; other < 100; ++other) {
      const M Q = rotation_exp<double>(angle(rng) * random_unit(rng)) * R;
      EXPECT_GE((R.transpose() * Mat).trace(), (Q.transpose() * Mat).trace() - 1e-12 * Mat.norm());
    }
    const Svd3<double> d = svd3<double>(trial % 3 == 0 ? Mat : random_map(rng));
    EXPECT_LT((nearest_rotation<double>(d.matrix()) - polar3(d).R).norm(), 1e-13);
  }
}

// The closed form for rank 2 (a triangle's in-plane products X Zᵀ, X and Z 3 × 2) is the SVD's answer, and it maps
// the plane of Z onto the plane of X keeping the orientations X and Z give them (tr(Rᵀ X Zᵀ) = σ1 + σ2 needs the
// 2 × 2 map between the planes to be a rotation); below rank 2 it is the SVD's answer itself.
TEST(NearestRotation, OfRankTwoIsTheSvdsAnswer) {
  std::mt19937 rng(12);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 400; ++trial) {
    Eigen::Matrix<double, 3, 2> X, Z;
    for (int k = 0; k < 6; ++k) X(k) = g(rng), Z(k) = g(rng);
    const M Mat = X * Z.transpose();
    const M R = nearest_rotation_of_rank_two<double>(Mat);
    EXPECT_LT((R - nearest_rotation<double>(Mat)).norm(), 1e-11) << "trial " << trial;
    const V n_x = X.col(0).cross(X.col(1)).normalized(), n_z = Z.col(0).cross(Z.col(1)).normalized();
    EXPECT_NEAR((R * n_z).dot(n_x), 1, 1e-11) << "trial " << trial;
  }
  const M rank_one = V(1, 2, 3) * V(-1, 0.5, 2).transpose();
  EXPECT_EQ(nearest_rotation_of_rank_two<double>(rank_one), nearest_rotation<double>(rank_one));
}

// Kabsch: points turned by a rotation and moved give back that rotation, whatever the move; with noise, no other
// rotation fits them better.
TEST(NearestRotation, FittedRotationRecoversATurnAndMovedPoints) {
  std::mt19937 rng(13);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(0, pi);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Matrix3Xd p(3, 7);
    for (Eigen::Index k = 0; k < p.size(); ++k) p(k) = g(rng);
    const M R = rotation_exp<double>(angle(rng) * random_unit(rng));
    const Eigen::Matrix3Xd q = (R * p).colwise() + V(g(rng), g(rng), g(rng));
    EXPECT_LT((fitted_rotation<double>(p, q) - R).norm(), 1e-12) << "trial " << trial;
    Eigen::Matrix3Xd noisy = q;
    for (Eigen::Index k = 0; k < noisy.size(); ++k) noisy(k) += 0.1 * g(rng);
    const M F = fitted_rotation<double>(p, noisy);
    const auto misfit = [&](const M& Q) {
      const Eigen::Matrix3Xd r = (noisy.colwise() - noisy.rowwise().mean()) - Q * (p.colwise() - p.rowwise().mean());
      return r.squaredNorm();
    };
    for (int other = 0; other < 20; ++other)
      EXPECT_LE(misfit(F), misfit(rotation_exp<double>(0.3 * angle(rng) * random_unit(rng)) * F) + 1e-12);
  }
}

/// The four homotopies of A built from its principal logarithms, and from ω shifted by `turns` turns.
template <class Check>
void for_each_homotopy(const M& A, int turns, Check check) {
  const Svd3<double> d = svd3<double>(A);
  const V omega = rotation_log<double>(d.U * d.V.transpose());
  const V branch = omega.norm() > 0 ? V(omega + 2 * pi * turns * omega.normalized()) : omega;
  check("linear", [&](double t) { return LinearHomotopy3<double>{A}(t); });
  check("polar", [&](double t) { return PolarHomotopy3<double>{branch, polar3(d).S}(t); });
  check("exp", [&](double t) { return ExpLogHomotopy3<double>(branch, polar3(d).S)(t); });
  const SvdHomotopy3<double> s = SvdHomotopy3<double>::of(A);
  const V omega_U = s.omega_U.norm() > 0 ? V(s.omega_U + 2 * pi * turns * s.omega_U.normalized()) : s.omega_U;
  check("svd", [&](double t) { return SvdHomotopy3<double>{omega_U, s.sigma, s.omega_V}(t); });
}

TEST(Homotopies3, StartAtIAndEndAtAOnEveryBranch) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 100; ++trial) {
    const M A = random_map(rng);
    for (int turns : {0, 1, -2})
      for_each_homotopy(A, turns, [&](const char* name, auto path) {
        EXPECT_LT((path(0.0) - M::Identity()).norm(), 4e-15) << name;  // exp-log's S^0 = V Vᵀ: a few ε
        EXPECT_LT((path(1.0) - A).norm(), 1e-13 * A.norm()) << name << " turns " << turns;
      });
  }
}

// det A^E(t) = det S^t = exp(t tr log S) > 0 for every t (the exp-log homotopy never inverts).
TEST(ExpLogHomotopy3, DeterminantIsExpOfTTraceLogS) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const M A = random_map(rng);
    const Svd3<double> d = svd3<double>(A);
    const ExpLogHomotopy3<double> path = ExpLogHomotopy3<double>::of(A);
    for (double t : {-0.5, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0, 1.5}) {
      const double expected = std::exp(t * log_stretch(d).trace());
      EXPECT_GT(path(t).determinant(), 0);
      EXPECT_NEAR(path(t).determinant() / expected, 1, 1e-12);  // the product's rounding, entries up to e^{1.5·log 8}
    }
  }
}

// The linear homotopy can leave GL⁺(3): for the half turn about z, A^L(1/2) = diag(0, 0, 1), exactly.
TEST(LinearHomotopy3, CanPassThroughASingularMap) {
  const M A = Eigen::Vector3d(-1, -1, 1).asDiagonal();  // a half turn about z
  EXPECT_EQ(LinearHomotopy3<double>{A}(0.5).determinant(), 0);
}

TEST(Homotopies3, LongDoubleInstantiates) {
  const Mat3<long double> A = (Mat3<long double>() << 1, 0.5L, 0, 0, 2, 0, 0.25L, 0, 1).finished();
  const ExpLogHomotopy3<long double> path = ExpLogHomotopy3<long double>::of(A);
  EXPECT_LT((path(1.0L) - A).norm(), 1e-17L);
  EXPECT_LT((PolarHomotopy3<long double>::of(A)(1.0L) - A).norm(), 1e-17L);
}

}  // namespace local3_test
