// The local library (theory/local): eq. (1) exactly over rationals; the polar decomposition, the
// rotation-only SVD and the four homotopies on adversarial GL+(2) matrices; the Real50 instantiations.
#include "checks/local/generators.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/local.hpp"

#include <numbers>

namespace affinterp::local::library_test {
namespace {

using exact::Rational;
using std::numbers::pi;

double relative_error(const Mat2<double>& got, const Mat2<double>& want) { return (got - want).norm() / want.norm(); }

TEST(AffineMap, MapsTheVerticesExactly) {
  Triangle<Rational> p, q;
  p << 0, 0, 2, 0, 3, 0;  // columns (0,0), (0,3), (2,0): thesis §2.2.4's P
  q << Rational(1) / 3, 5, -2, Rational(7) / 2, 1, Rational(-1) / 5;
  const AffineMap<Rational> map = affine_map(p, q);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(Vec2<Rational>(map.A.lazyProduct(p.col(k)) + map.d), Vec2<Rational>(q.col(k)));
  EXPECT_EQ(map.A_hat.row(2), (Eigen::Matrix<Rational, 1, 3>() << 0, 0, 1).finished());
}

TEST(AffineMap, RejectsADegenerateSource) {
  Triangle<Rational> p, q;
  p << 0, 1, 2, 0, 1, 2;  // collinear
  q << 0, 1, 0, 0, 0, 1;
  EXPECT_THROW(affine_map(p, q), std::invalid_argument);
}

RC_GTEST_PROP(AffineMap, MapsAdversarialTrianglesInDouble, ()) {
  const Triangle<double> p = *testing::triangle(), q = *testing::triangle();
  RC_PRE(testing::area_ratio(p) > 1e-3);
  const AffineMap<double> map = affine_map(p, q);
  // Rounding in H(p)⁻¹ grows with how far p lies from the origin compared with its size.
  const double reach = p.cwiseAbs().maxCoeff(), size2 = testing::area_ratio(p) * (p.col(1) - p.col(0)).squaredNorm();
  const double tolerance = 1e-12 * (map.A.norm() * reach + map.d.norm() + q.norm()) * (1 + reach * reach / size2);
  for (int k = 0; k < 3; ++k) RC_ASSERT((map.A * p.col(k) + map.d - q.col(k)).norm() <= tolerance);
  const double row_tolerance = 1e-12 * (1 + reach * reach / size2);
  RC_ASSERT(std::abs(map.A_hat(2, 0)) * reach <= row_tolerance);  // entries of units 1/length
  RC_ASSERT(std::abs(map.A_hat(2, 1)) * reach <= row_tolerance);
  RC_ASSERT(std::abs(map.A_hat(2, 2) - 1) <= row_tolerance);
}

TEST(PrincipalAngle, LiesInTheHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(principal_angle(pi), pi);
  EXPECT_DOUBLE_EQ(principal_angle(-pi), pi);
  EXPECT_DOUBLE_EQ(principal_angle(3 * pi), pi);
  EXPECT_NEAR(principal_angle(-4 * pi / 3), 2 * pi / 3, 1e-15);
}

TEST(PolarDecomposition, RejectsNonPositiveDeterminant) {
  Mat2<double> A;
  A << 1, 0, 0, -1;
  EXPECT_THROW(polar_decomposition(A), std::invalid_argument);
  EXPECT_THROW(svd(A), std::invalid_argument);
}

TEST(PolarDecomposition, OfMinusIdentityIsTheHalfTurn) {
  const Polar<double> polar = polar_decomposition<double>(-identity2<double>());
  EXPECT_DOUBLE_EQ(polar.theta, pi);
  EXPECT_LT((polar.S - identity2<double>()).norm(), 1e-15);
}

RC_GTEST_PROP(PolarDecomposition, ReassemblesWithPrincipalAngleAndPositiveS, ()) {
  const Mat2<double> A = *testing::gl_plus();
  const Polar<double> polar = polar_decomposition(A);
  RC_ASSERT(polar.theta > -pi);
  RC_ASSERT(polar.theta <= pi);
  RC_ASSERT(polar.S(0, 1) == polar.S(1, 0));
  RC_ASSERT(polar.S(0, 0) > 0);
  RC_ASSERT(det2(polar.S) > 0);
  RC_ASSERT(relative_error(rotation(polar.theta) * polar.S, A) < 1e-13);
}

RC_GTEST_PROP(Svd, ReassemblesWithOrderedPositiveSingularValues, ()) {
  const Svd<double> drawn = *testing::gl_plus_parameters();
  const Mat2<double> A = drawn.matrix();
  const Svd<double> decomposition = svd(A);
  RC_ASSERT(decomposition.x >= decomposition.y);
  RC_ASSERT(decomposition.y > 0);
  RC_ASSERT(std::abs(decomposition.x - drawn.x) <= 1e-13 * drawn.x);
  RC_ASSERT(std::abs(decomposition.y - drawn.y) <= 1e-13 * drawn.x);
  RC_ASSERT(relative_error(decomposition.matrix(), A) < 1e-13);
}

RC_GTEST_PROP(PolarFromSvd, AgreesWithThePolarDecompositionModuloTwoPi, ()) {
  const Mat2<double> A = *testing::gl_plus();
  const Polar<double> direct = polar_decomposition(A), via_svd = polar_from_svd(svd(A));
  RC_ASSERT(std::abs(std::remainder(direct.theta - via_svd.theta, 2 * pi)) < 1e-12);
  RC_ASSERT(relative_error(via_svd.S, direct.S) < 1e-12);
}

RC_GTEST_PROP(SpdPower, IsTheMatrixPowerOfS, ()) {
  const Mat2<double> S = *testing::spd();
  const Svd<double> S_eigen = svd(S);
  RC_ASSERT(std::abs(S_eigen.alpha + S_eigen.beta) < 1e-15);
  RC_ASSERT(relative_error(spd_power(S_eigen, 1.0), S) < 1e-13);
  RC_ASSERT(relative_error(spd_power(S_eigen, 2.0), S * S) < 1e-12);
  const Mat2<double> root = spd_power(S_eigen, 0.5);
  RC_ASSERT(relative_error(root * root, S) < 1e-12);
}

RC_GTEST_PROP(Homotopies, StartAtIdentityAndEndAtA, ()) {
  const Mat2<double> A = *testing::gl_plus();
  const Mat2<double> I = identity2<double>();
  const auto check = [&](const auto& homotopy) {
    RC_ASSERT((homotopy(0.0) - I).norm() < 1e-15);
    RC_ASSERT(relative_error(homotopy(1.0), A) < 1e-12);
  };
  check(LinearHomotopy<double>{A});
  check(SvdHomotopy<double>::of(A));
  check(PolarHomotopy<double>::of(A));
  check(ExpLogHomotopy<double>::of(A));
}

RC_GTEST_PROP(Homotopies, AcceptAnyRepresentativeOfTheta, ()) {
  const Mat2<double> A = *testing::gl_plus();
  const int k = *rc::gen::inRange(-3, 4);
  const Polar<double> polar = polar_decomposition(A);
  const double theta = polar.theta + 2 * pi * k;
  RC_ASSERT(relative_error(PolarHomotopy<double>{theta, polar.S}(1.0), A) < 1e-12);
  const ExpLogHomotopy<double> exp_log(theta, polar.S);
  RC_ASSERT(relative_error(exp_log(1.0), A) < 1e-12);
  // Half-way, the extra turns show: the rotation is by θ/2 + πk.
  RC_ASSERT(relative_error(exp_log(0.5), rotation(theta / 2) * spd_power(svd(polar.S), 0.5)) < 1e-12);
}

RC_GTEST_PROP(ExpLogHomotopy, DeterminantIsTheProductOfSingularValuesToThePowerT, ()) {
  const Mat2<double> A = *testing::gl_plus();
  const double t = *testing::uniform(-2, 3);
  const Svd<double> s = svd(A);
  const double expected = std::pow(s.x, t) * std::pow(s.y, t);
  const Mat2<double> A_t = ExpLogHomotopy<double>::of(A)(t);
  // det by a·d − b·c loses ε·‖A(t)‖² to cancellation, and y (recomputed from S) is only known to a
  // relative ε·x/y, which y^t carries as t·ε·x/y.
  const double tolerance = 1e-12 * A_t.squaredNorm() + 1e-14 * (1 + std::abs(t)) * (s.x / s.y) * expected;
  RC_ASSERT(std::abs(det2(A_t) - expected) <= tolerance);
}

TEST(Homotopies, LinearIsExactOverRationals) {
  Mat2<Rational> A;
  A << -1, 0, 0, -1;
  const Mat2<Rational> half_way = LinearHomotopy<Rational>{A}(Rational(1) / 2);
  for (const Rational& entry : half_way.reshaped()) EXPECT_EQ(entry, 0);
}

TEST(Homotopies, InstantiateOverReal50) {
  using exact::Real50;
  Mat2<Real50> A;
  A << Real50(-1) / 4, Real50(-3) * sqrt(Real50(3)) / 4, Real50(3) * sqrt(Real50(3)) / 4, Real50(-5) / 4;
  const Svd<Real50> s = svd(A);
  EXPECT_LT(abs(s.x - 2), Real50("1e-45"));
  EXPECT_LT(abs(s.y - 1), Real50("1e-45"));
  EXPECT_LT((ExpLogHomotopy<Real50>::of(A)(Real50(1)) - A).norm(), Real50("1e-45"));
  EXPECT_LT((SvdHomotopy<Real50>::of(A)(Real50(1)) - A).norm(), Real50("1e-45"));
  EXPECT_LT((PolarHomotopy<Real50>::of(A)(Real50(1)) - A).norm(), Real50("1e-45"));
}

}  // namespace
}  // namespace affinterp::local::library_test
