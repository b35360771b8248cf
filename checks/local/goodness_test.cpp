// The exact goodness deciders (theory/local/goodness.hpp) against brute force: dense sampling of t and
// of the direction v in double precision, and exact witnesses whenever a decider says "not good".
#include "theory/local/goodness.hpp"
#include "checks/local/generators.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/quadratic_field.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <cmath>
#include <numbers>

namespace affinterp::local::goodness_test {
namespace {

using exact::Rational;

/// A matrix with entries k/4, |k| ≤ 12: small rationals where ties and boundaries are common.
rc::Gen<Mat2<Rational>> small_rational_matrix() {
  return rc::gen::map(rc::gen::container<std::vector<int>>(4, rc::gen::inRange(-12, 13)),
                      [](const std::vector<int>& k) {
                        Mat2<Rational> B;
                        B << Rational(k[0]) / 4, Rational(k[1]) / 4, Rational(k[2]) / 4, Rational(k[3]) / 4;
                        return B;
                      });
}

/// I + N + kJ with N ⪰ 0 (sym(B − I) ⪰ 0: good for norm), or a symmetric contraction plus kJ (often
/// good through BᵀB ⪯ sym B), or a small rational matrix: the three outcomes of the norm decider.
rc::Gen<Mat2<Rational>> norm_test_matrix() {
  const auto quarter = [](int lo, int hi) {
    return rc::gen::map(rc::gen::inRange(lo, hi + 1), [](int k) { return Rational(k) / 4; });
  };
  const auto shaped = [=](Rational offset, int max_diagonal) {
    return rc::gen::map(
        rc::gen::tuple(quarter(0, max_diagonal), quarter(0, max_diagonal), quarter(-7, 7), quarter(-2, 2)),
        [offset](const std::tuple<Rational, Rational, Rational, Rational>& p) {
          const auto& [a, b, c, k] = p;
          const Rational h = c * std::min(a, b) / 8;  // h² < ab: N ⪰ 0
          Mat2<Rational> B;
          B << offset + a, h - k / 8, h + k / 8, offset + b;
          return B;
        });
  };
  return rc::gen::weightedOneOf<Mat2<Rational>>({{2, small_rational_matrix()}, {1, shaped(1, 12)}, {1, shaped(0, 4)}});
}

Mat2<double> to_double(const Mat2<Rational>& B) {
  return B.unaryExpr([](const Rational& q) { return static_cast<double>(q); });
}

/// ‖((1−t)I + tB)v‖² sampled at t = j/n.
std::vector<double> sampled_norms(const Mat2<double>& B, double phi, int n) {
  std::vector<double> f;
  for (int j = 0; j <= n; ++j) {
    const double t = static_cast<double>(j) / n;
    const Eigen::Vector2d v(std::cos(phi), std::sin(phi));
    f.push_back((((1 - t) * Eigen::Matrix2d::Identity() + t * B) * v).squaredNorm());
  }
  return f;
}

bool rises_and_falls(const std::vector<double>& f, double tolerance) {
  bool rise = false, fall = false;
  for (std::size_t j = 0; j + 1 < f.size(); ++j) {
    rise = rise || f[j + 1] - f[j] > tolerance;
    fall = fall || f[j] - f[j + 1] > tolerance;
  }
  return rise && fall;
}

RC_GTEST_PROP(GoodForArea, AgreesWithDenseSamplingAndExactWitnesses, ()) {
  const Mat2<Rational> B = *small_rational_matrix();
  const Quadratic<Rational> det = blend_determinant(B);
  // The recovered polynomial is det((1−t)I + tB) at further exact points.
  for (const Rational& t : {Rational(-3), Rational(1) / 3, Rational(5) / 7, Rational(4)})
    RC_ASSERT(det(t) == det2<Rational>(scaled(Rational(1) - t, identity2<Rational>()) + scaled(t, B)));
  std::vector<double> samples;
  for (int j = 0; j <= 2000; ++j) samples.push_back(static_cast<double>(det(Rational(j) / 2000)));
  const bool sampled_positive = *std::min_element(samples.begin(), samples.end()) > 0;
  const bool sampled_monotone = !rises_and_falls(samples, 1e-12);
  if (positive_on_unit_interval(det)) {
    RC_ASSERT(sampled_positive);
  } else {  // an exact witness: t ∈ {0, 1, interior critical point} with det ≤ 0
    const auto t = interior_critical_point(det);
    RC_ASSERT(det(0) <= 0 || det(1) <= 0 || (t && det(*t) <= 0));
  }
  if (monotone_on_unit_interval(det)) {
    RC_ASSERT(sampled_monotone);
  } else {  // the interior critical point is a strict extreme
    const auto t = interior_critical_point(det);
    RC_ASSERT(t.has_value());
    RC_ASSERT((det(*t) - det(0)) * (det(*t) - det(1)) > 0);
  }
}

RC_GTEST_PROP(GoodForNorm, AgreesWithDenseSamplingAndExactWitnesses, ()) {
  const Mat2<Rational> B = *norm_test_matrix();
  RC_CLASSIFY(good_for_norm(B), "good for norm");
  const Mat2<double> B_double = to_double(B);
  constexpr int directions = 720, times = 200;
  std::optional<double> worst_phi;
  double worst_margin = 0;
  const NormForms<Rational> forms(B);
  const Mat2<double> P = to_double(forms.P), Q = to_double(forms.Q);
  for (int k = 0; k < directions; ++k) {
    const double phi = std::numbers::pi * k / directions;
    const Eigen::Vector2d v(std::cos(phi), std::sin(phi));
    const double margin = std::min(-v.dot(P * v), v.dot(Q * v));
    if (margin > worst_margin) worst_margin = margin, worst_phi = phi;
  }
  if (good_for_norm(B)) {
    for (int k = 0; k < directions; ++k)
      RC_ASSERT(!rises_and_falls(sampled_norms(B_double, std::numbers::pi * k / directions, times), 1e-9));
  } else {
    // Not good: a direction v, rounded to rationals, where the norm provably dips inside (0, 1).
    RC_ASSERT(worst_phi.has_value());
    const Vec2<Rational> v(exact::from_double(std::cos(*worst_phi)), exact::from_double(std::sin(*worst_phi)));
    RC_ASSERT(norm_dips(B, v));
    const Rational t = norm_dip_time(B, v);
    const auto norm2 = [&](const Rational& s) {
      return Vec2<Rational>((scaled(Rational(1) - s, identity2<Rational>()) + scaled(s, B)).lazyProduct(v))
          .squaredNorm();
    };
    RC_ASSERT(t > 0);
    RC_ASSERT(t < 1);
    RC_ASSERT(norm2(t) < norm2(0));
    RC_ASSERT(norm2(t) < norm2(1));
  }
}

/// For symmetric positive definite S: both eigenvalues ≥ 1, or both ≤ 1 (an independent derivation in S's eigenbasis).
bool eigenvalues_on_one_side_of_one(const Mat2<Rational>& S) {
  const Mat2<Rational> M = S - identity2<Rational>();
  return positive_semidefinite<Rational>(M) || positive_semidefinite<Rational>(-M);
}

RC_GTEST_PROP(GoodForNorm, ForSymmetricSMeansEigenvaluesOnOneSideOfOne, ()) {
  const Rational x = Rational(*rc::gen::inRange(1, 17)) / 4, y = Rational(*rc::gen::inRange(1, 17)) / 4;
  const Rational h = Rational(*rc::gen::inRange(-7, 8)) / 8 * std::min(x, y);  // h² < xy
  Mat2<Rational> S;
  S << x, h, h, y;
  RC_ASSERT(good_for_norm(S) == eigenvalues_on_one_side_of_one(S));
}

TEST(GoodForNorm, OnTheBoundaryOfThm225) {
  Mat2<Rational> S;
  S << 2, 2, 2, 5;  // (x−1)(y−1) = h²: eigenvalues 1 and 6
  EXPECT_TRUE(good_for_norm(S));
  S(0, 1) = S(1, 0) = Rational(201) / 100;
  EXPECT_FALSE(good_for_norm(S));
  EXPECT_TRUE(good_for_norm<Rational>(identity2<Rational>()));
}

TEST(GoodForArea, MinusIdentityCollapses) {
  const Mat2<Rational> B = -identity2<Rational>();
  EXPECT_FALSE(positive_on_unit_interval(blend_determinant(B)));
  EXPECT_FALSE(good_for_area(B));
}

TEST(QuadraticSurd, ArithmeticAndOrderAreExact) {
  const QSqrt3 r = QSqrt3::root();
  EXPECT_EQ((QSqrt3(1) + r) * (QSqrt3(1) - r), QSqrt3(-2));
  EXPECT_EQ(r * r, QSqrt3(3));
  EXPECT_EQ((QSqrt3(1) / (QSqrt3(2) + r)) * (QSqrt3(2) + r), QSqrt3(1));
  EXPECT_GT(QSqrt3(2) - r, QSqrt3(0));
  EXPECT_LT(QSqrt3(Rational(173) / 100) - r, QSqrt3(0));
  EXPECT_GT(QSqrt3(Rational(174) / 100) - r, QSqrt3(0));
  EXPECT_LT(QSqrt3(Rational(-7)), -r);
  EXPECT_THROW(QSqrt3(1) / QSqrt3(0), std::domain_error);
}

TEST(QuadraticSurd, RunsTheDecidersOfTheThesisExample) {
  const QSqrt3 r = QSqrt3::root();
  Mat2<QSqrt3> A;  // thesis §2.2.4
  A << QSqrt3(Rational(-1) / 4), QSqrt3(0, Rational(-3) / 4), QSqrt3(0, Rational(3) / 4), QSqrt3(Rational(-5) / 4);
  EXPECT_FALSE(good_for_area(A));
  EXPECT_FALSE(good_for_norm(A));
  EXPECT_EQ(det2(A), QSqrt3(2));
  (void)r;
}

}  // namespace
}  // namespace affinterp::local::goodness_test
