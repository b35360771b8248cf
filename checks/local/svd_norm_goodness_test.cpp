// The exact SVD-norm decider (theory/local/svd_norm_goodness.hpp, Lemmas L9 + L12) against the brute-force
// sampler it replaced (checks/local/svd_norm_sampling.hpp) on the sampler's clear cases, against the exact
// decider of the linear homotopy at β = 0, and on the grid case the sampler got wrong.
#include "theory/local/svd_norm_goodness.hpp"

#include "checks/local/svd_norm_sampling.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/svd_homotopy.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace affinterp::local::svd_norm_goodness_test {
namespace {

using exact::Rational;
using exact::Real50;

TEST(SvdNormGoodness, MarginIsGOfLemmaL9AtTimeOne) {
  // x = 2, y = 1, β = 1: G_1 = [[2, −3/2], [−3/2, 0]], 4 det G_1 = −9.
  EXPECT_EQ(svd_norm_margin<Rational>(2, 1, 1), Rational(-9));
  EXPECT_FALSE(svd_good_for_norm<Rational>(2, 1, 1));
  EXPECT_TRUE(svd_good_for_norm<Rational>(2, 1, 0));                 // β = 0: D's own linear homotopy, good
  EXPECT_TRUE(svd_good_for_norm<Rational>(3, 3, 100));               // x = y: D commutes with every rotation
  EXPECT_FALSE(svd_good_for_norm<Rational>(2, Rational(1) / 2, 0));  // (x − 1)(y − 1) < 0
}

TEST(SvdNormGoodness, AtPiMultiplesDecidesTheQuarterTurn) {
  EXPECT_FALSE(svd_good_for_norm_at_pi_multiple(2, 1, Rational(1) / 2));
  EXPECT_TRUE(svd_good_for_norm_at_pi_multiple(3, 3, Rational(1) / 2));
  // 4·2·3·1·2 / (1·5)² = 48/25 < π² r² exactly when r² > 48/(25π²) ≈ 0.1945: r = 1/4 good, r = 1/2 not.
  EXPECT_TRUE(svd_good_for_norm_at_pi_multiple(2, 3, Rational(1) / 4));
  EXPECT_FALSE(svd_good_for_norm_at_pi_multiple(2, 3, Rational(1) / 2));
  // r ≈ sqrt(48/25)/π to 45 digits puts a / c = 48 / (25 r²) within the 40-digit bracket of π²: it refuses.
  const Rational r = exact::parse_rational(
      "441063116337433639609061198650375553117909184/"
      "1000000000000000000000000000000000000000000000");
  EXPECT_THROW(svd_good_for_norm_at_pi_multiple(2, 3, r), std::domain_error);
}

TEST(SvdNormGoodness, TheSamplersMisclassifiedGridCaseFailsAlongAnExplicitDirection) {
  // x = 1/8, y = 1/4, β = 2π·47/48: the 96 × 96 sampler calls it good; G(1) < 0.
  EXPECT_FALSE(svd_good_for_norm_at_pi_multiple(Rational(1) / 8, Rational(1) / 4, Rational(47) / 24));
  // A direction as in Lemma L9's proof (φ = −5.49916364201): ‖A_s(t)v‖² falls near t = 0 and rises near 1.
  const SvdHomotopy<Real50> A{{Real50(0), Real50(1) / 8, Real50(1) / 4, 2 * pi<Real50>() * 47 / 48}};
  const Real50 phi("-5.49916364201");
  const Vec2<Real50> v(cos(phi), sin(phi));
  const auto f = [&](const Real50& t) { return Real50((A(t) * v).squaredNorm()); };
  EXPECT_LT(f(Real50("0.001")), f(Real50(0)));
  EXPECT_GT(f(Real50(1)), f(Real50("0.999")));
}

/// |G(1)| against the size of its two terms: a case is clear for a sampler when this is at least 1/10.
double relative_margin(double x, double y, double beta) {
  const double first = 4 * x * y * (x - 1) * (y - 1), second = beta * beta * (x - y) * (x - y) * (x + y) * (x + y);
  return std::abs(first - second) / (std::abs(first) + second + 1e-300);
}

RC_GTEST_PROP(SvdNormGoodness, AgreesWithTheSamplerOnItsClearCases, ()) {
  const int i = *rc::gen::inRange(1, 13), j = *rc::gen::inRange(1, 13), k = *rc::gen::inRange(-48, 49);
  const Rational x = Rational(i) / 4, y = Rational(j) / 4, r = Rational(k) / 24;  // β = πr ∈ [−2π, 2π]
  const double beta = std::numbers::pi * k / 24;
  const bool exact_good = svd_good_for_norm_at_pi_multiple(x, y, r);
  const bool sampled_good = !svd_norm_failure(static_cast<double>(x), static_cast<double>(y), beta, {}).has_value();
  // A sampled failure is a genuine rise and fall (far above rounding): the exact decider must agree.
  if (!sampled_good) RC_ASSERT(!exact_good);
  if (relative_margin(static_cast<double>(x), static_cast<double>(y), beta) >= 0.1)
    RC_ASSERT(exact_good == sampled_good);
}

RC_GTEST_PROP(SvdNormGoodness, WithoutRightRotationIsTheLinearHomotopyOfD, ()) {
  const Rational x = Rational(*rc::gen::inRange(1, 41)) / 10, y = Rational(*rc::gen::inRange(1, 41)) / 10;
  Mat2<Rational> D;
  D << x, 0, 0, y;
  RC_ASSERT(svd_good_for_norm<Rational>(x, y, 0) == good_for_norm(D));
}

TEST(SvdNormSampling, FindsTheQuarterTurnFailure) {
  // D = diag(2, 1), β = π/2: ‖A_s(t)e1‖² = 1, 13/8, 1 at t = 0, ½, 1.
  EXPECT_NEAR(svd_norm_squared(2, 1, std::numbers::pi / 2, 0, 0.5), 13.0 / 8, 1e-15);
  const auto witness = svd_norm_failure(2, 1, std::numbers::pi / 2, {});
  ASSERT_TRUE(witness.has_value());
  const auto f = [&](double t) { return svd_norm_squared(2, 1, std::numbers::pi / 2, witness->phi, t); };
  EXPECT_GT((f(witness->t_b) - f(witness->t_a)) * (f(witness->t_b) - f(witness->t_c)), 0);
}

}  // namespace
}  // namespace affinterp::local::svd_norm_goodness_test
