// Properties of ours (exp, S^t, log) on random symmetric matrices, with RapidCheck.
#include "theory/linalg/symmetric.hpp"
#include "theory/sym3/affinterp.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <iomanip>
#include <vector>

namespace affinterp::sym3::properties_test {
namespace {

/// Symmetric matrices with entries on a grid of step 1/1000 in [−bound, bound].
rc::Gen<Mat3> symmetric(double bound) {
  const int n = static_cast<int>(bound * 1000);
  return rc::gen::map(rc::gen::container<std::vector<int>>(6, rc::gen::inRange(-n, n + 1)),
                      [](const std::vector<int>& e) {
                        Mat3 S;
                        S << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
                        return Mat3(S / 1000.0);
                      });
}

/// SPD matrices MᵀM + I/10 with M from the same grid.
rc::Gen<Mat3> spd() {
  return rc::gen::map(symmetric(2.0),
                      [](const Mat3& M) { return Mat3(linalg::outer_gram(M.transpose()) + 0.1 * Mat3::Identity()); });
}

RC_GTEST_PROP(Sym3Properties, ExpIsSymmetricPositiveDefinite, ()) {
  const Mat3 E = exp_affinterp(*symmetric(5.0));
  RC_ASSERT(E == E.transpose());
  RC_ASSERT(Eigen::LLT<Mat3>(E).info() == Eigen::Success);
}

RC_GTEST_PROP(Sym3Properties, DeterminantIsExpOfTrace, ()) {
  const Mat3 S = *symmetric(3.0);
  const double expected = std::exp(S.trace());
  const Mat3 E = exp_affinterp(S);
  // The determinant of E in double is itself only accurate to about ε‖E‖³.
  RC_ASSERT(std::abs(E.determinant() - expected) <= 1e-14 * std::pow(E.norm(), 3) * std::max(1.0, S.norm()));
}

RC_GTEST_PROP(Sym3Properties, ExpOfMinusSIsTheInverse, ()) {
  const Mat3 S = *symmetric(2.0);
  const Mat3 E = exp_affinterp(S), F = exp_affinterp(-S);
  RC_ASSERT((E * F - Mat3::Identity()).norm() <= 1e-14 * E.norm() * F.norm() * std::max(1.0, S.norm()));
}

RC_GTEST_PROP(Sym3Properties, PowersMultiply, ()) {
  const Mat3 S = *spd();
  const double t = *rc::gen::inRange(-1000, 2001) / 1000.0;
  const Mat3 product = pow_spd(S, t) * pow_spd(S, 1.0 - t);
  const double condition = S.norm() * S.inverse().norm();
  RC_ASSERT((product - S).norm() <= 1e-13 * condition * condition * S.norm());
}

RC_GTEST_PROP(Sym3Properties, LogInvertsExp, ()) {
  const Mat3 S = *symmetric(2.0);
  RC_ASSERT((log_spd(exp_affinterp(S)) - S).norm() <= 1e-13 * std::max(1.0, S.norm()) * std::exp(2 * S.norm()));
}

TEST(Sym3Properties, PowerEndpointsAndSquareRoot) {
  Mat3 S;
  S << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  EXPECT_LE((pow_spd(S, 0.0) - Mat3::Identity()).norm(), 1e-15);
  EXPECT_LE((pow_spd(S, 1.0) - S).norm(), 1e-14);
  const Mat3 R = pow_spd(S, 0.5);
  EXPECT_LE((R * R - S).norm(), 1e-14);
  EXPECT_THROW(log_spd(-S), std::domain_error);
}

TEST(Sym3Properties, RepeatedEigenvaluesNeedNoSpecialCase) {
  for (const double a : {0.0, 1.0, -3.5, 700.0}) {
    const Mat3 S = a * Mat3::Identity();
    EXPECT_LE((exp_affinterp(S) - std::exp(a) * Mat3::Identity()).norm(), 2e-16 * std::exp(a));
  }
  EXPECT_LE((log_spd(2.0 * Mat3::Identity()) - std::log(2.0) * Mat3::Identity()).norm(), 1e-16);
}

}  // namespace
}  // namespace affinterp::sym3::properties_test
