// The certified references on every family of experiments/inputs/sym3/families.hpp: the balls of exp S,
// the eigenvalues, S^t and log S contain the 100-digit Boost references (theory/sym3/reference.hpp), their
// radii are as small as the target, they certify the error of ours, and on the whole-double-range family
// every result is decided (certified or overflowing) and agrees with Arb's arb_mat_exp where both apply.
#include "experiments/inputs/sym3/families.hpp"
#include "checks/certified/helpers.hpp"
#include "theory/linalg/symmetric.hpp"
#include "theory/sym3/affinterp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace affinterp::certified::families_test {
namespace {

using sym3::Family;
using sym3::Mat3R100;
using testing::contains;
using testing::Real100;

constexpr std::size_t kDraws = 6;
constexpr std::uint64_t kSeed = 5;

/// V diag(f(λ)) Vᵀ from the 100-digit Jacobi reference.
template <class F>
Mat3R100 reference_function(const Mat3& S, F f) {
  const sym3::ReferenceEigen e = sym3::reference_eigen(sym3::to_real100(S));
  sym3::Vec3R100 values;
  for (int k = 0; k < 3; ++k) values(k) = f(e.lambda(k));
  return linalg::congruence(e.V, values);
}

Real100 frobenius(const Mat3R100& E) { return sqrt(E.cwiseAbs2().sum()); }

TEST(CertifiedFamilies, BallsContainTheBoostReferencesWithTinyRadii) {
  for (const Family& family : sym3::families()) {
    if (family.whole_double_range) continue;  // beyond the Boost references
    double worst_exp_radius = 0, worst_log_radius = 0, worst_error_radius = 0;
    for (const Mat3& S : family.draw(family, kSeed, kDraws)) {
      // exp: certified at the default target, containing the 100-digit Jacobi reference.
      const CertifiedMatrix e = certified::exp(S);
      ASSERT_EQ(e.status, Status::certified) << family.name;
      EXPECT_LE(e.bits, 256) << family.name;
      const Mat3R100 E = sym3::exp_by_eigen(sym3::to_real100(S));
      EXPECT_TRUE(contains(e.value, E, Real100("1e-90") * frobenius(E))) << family.name;
      const double relative_radius = e.value.relative_radius();
      EXPECT_LE(relative_radius, 0x1p-100) << family.name;
      worst_exp_radius = std::max(worst_exp_radius, relative_radius);

      // The error of ours is certified: its ball's radius is below 10⁻³ of it (or it is exactly 0).
      const Ball error = relative_error(sym3::exp_affinterp(S), e.value);
      EXPECT_TRUE(error.mid == 0 || certifies(error)) << family.name << ": " << error.mid << " ± " << error.rad;
      if (error.mid > 0) worst_error_radius = std::max(worst_error_radius, error.rad / error.mid);

      // Eigenvalues, ascending, containing the reference's.
      const CertifiedEigenvalues l = certified::eigenvalues(S);
      ASSERT_EQ(l.status, Status::certified) << family.name;
      const sym3::ReferenceEigen reference = sym3::reference_eigen(sym3::to_real100(S));
      const Real100 scale =
          std::max({Real100(1), Real100(abs(reference.lambda(2))), Real100(abs(reference.lambda(0)))});
      for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(contains(l.value, k, 0, reference.lambda(k), Real100("1e-90") * scale)) << family.name << " " << k;

      // log and S^(1/2), S^(−0.7) where S is positive definite: containing the reference's (whose own
      // error grows like 10⁻⁹⁸ κ₂).
      const CertifiedMatrix lg = certified::log_spd(S);
      if (lg.status == Status::not_spd) continue;
      ASSERT_EQ(lg.status, Status::certified) << family.name;
      const Real100 kappa = reference.lambda(2) / reference.lambda(0);
      const Mat3R100 L = reference_function(S, [](const Real100& x) { return log(x); });
      EXPECT_TRUE(contains(lg.value, L, Real100("1e-90") * (kappa + frobenius(L)))) << family.name;
      worst_log_radius = std::max(worst_log_radius, lg.value.relative_radius());
      for (const double t : {0.5, -0.7}) {
        const CertifiedMatrix p = certified::pow_spd(S, t);
        ASSERT_EQ(p.status, Status::certified) << family.name;
        const Mat3R100 P = reference_function(S, [t](const Real100& x) { return pow(x, Real100(t)); });
        EXPECT_TRUE(contains(p.value, P, Real100("1e-90") * kappa * frobenius(P))) << family.name << " t=" << t;
      }
    }
    std::printf("%-20s exp radius/‖exp S‖ ≤ %.1e, log radius/‖log S‖ ≤ %.1e, error-ball radius/error ≤ %.1e\n",
                family.name.c_str(), worst_exp_radius, worst_log_radius, worst_error_radius);
  }
}

TEST(CertifiedFamilies, WholeDoubleRangeIsDecided) {
  const auto family = std::ranges::find_if(sym3::families(), &Family::whole_double_range);
  ASSERT_NE(family, sym3::families().end());
  int overflows = 0, cross_checked = 0;
  long most_bits = 0;
  for (const Mat3& S : family->draw(*family, kSeed, 60)) {
    const CertifiedMatrix e = certified::exp(S);
    ASSERT_NE(e.status, Status::too_wide);
    most_bits = std::max(most_bits, e.bits);
    if (e.status == Status::overflows) {
      ++overflows;
      continue;
    }
    // Arb's Taylor method as an independent check, where ‖S‖ keeps its squarings few.
    const CertifiedEigenvalues l = certified::eigenvalues(S);
    if (std::max(std::abs(l.value.mid(0)), std::abs(l.value.mid(2))) > 1000) continue;
    const CertifiedMatrix taylor = certified::exp_taylor(S, 512);
    if (taylor.status != Status::certified) continue;
    ++cross_checked;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Ball a = e.value.entry(i, j), b = taylor.value.entry(i, j);
        EXPECT_TRUE(a.lower() <= b.upper() && b.lower() <= a.upper()) << i << j;
      }
  }
  std::printf("full-range: %d of 60 overflow, %d cross-checked with arb_mat_exp, at most %ld bits\n", overflows,
              cross_checked, most_bits);
  EXPECT_GT(cross_checked, 10);
}

// The 50-digit Boost references that thesis.exp.accuracy keeps as a cross-check lie in Arb's balls (widened
// by their own error, about 10⁻⁴⁸ of ‖exp S‖_F) on every family they cover.
TEST(CertifiedFamilies, FiftyDigitReferencesLieInTheBalls) {
  for (const Family& family : sym3::families()) {
    if (family.whole_double_range) continue;
    for (const Mat3& S : family.draw(family, kSeed, 4)) {
      const CertifiedMatrix e = certified::exp(S);
      ASSERT_EQ(e.status, Status::certified) << family.name;
      const sym3::Mat3R50 reference = sym3::reference_exp(S);
      Mat3R100 E;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) E(i, j) = Real100(reference(i, j));
      EXPECT_TRUE(contains(e.value, E, Real100("1e-45") * frobenius(E))) << family.name;
    }
  }
}

// The far-apart family (λmax − λmid > 709, λmax across exp's overflow) is decided everywhere: exp S
// overflows for some matrices and is certified finite for the others.
TEST(CertifiedFamilies, FarApartFamilyIsDecided) {
  const auto family = std::ranges::find(sym3::families(), std::string("far-apart"), &Family::name);
  ASSERT_NE(family, sym3::families().end());
  int overflows = 0, finite = 0;
  for (const Mat3& S : family->draw(*family, kSeed, 40)) {
    const CertifiedMatrix e = certified::exp(S);
    ASSERT_NE(e.status, Status::too_wide);
    (e.status == Status::overflows ? overflows : finite) += 1;
  }
  EXPECT_GT(overflows, 0);
  EXPECT_GT(finite, 0);
}

}  // namespace
}  // namespace affinterp::certified::families_test
