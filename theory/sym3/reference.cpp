#include "theory/sym3/reference.hpp"

#include "theory/linalg/symmetric.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace affinterp::sym3 {

using exact::Real100;
using exact::Real50;

namespace {

Real100 frobenius(const Mat3R100& A) {
  Real100 sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sum += A(i, j) * A(i, j);
  return sqrt(sum);
}

/// The references define exp S and the spectrum of a symmetric S; a non-symmetric input is a caller's
/// bug (the two methods would read it differently), so it is refused rather than silently symmetrised.
template <class Matrix>
const Matrix& require_symmetric(const Matrix& S) {
  if (!(S == S.transpose())) throw std::invalid_argument("sym3 reference: the matrix is not symmetric");
  return S;
}

Real100 off_diagonal(const Mat3R100& A) { return sqrt(A(0, 1) * A(0, 1) + A(0, 2) * A(0, 2) + A(1, 2) * A(1, 2)); }

}  // namespace

ReferenceEigen reference_eigen(const Mat3R100& S) {
  Mat3R100 A = require_symmetric(S);
  Mat3R100 V = Mat3R100::Identity();
  const Real100 tolerance = Real100("1e-98") * frobenius(S);
  constexpr std::array<std::array<int, 2>, 3> pairs{{{0, 1}, {0, 2}, {1, 2}}};
  for (int sweep = 0; sweep < 100 && off_diagonal(A) > tolerance; ++sweep) {
    for (const auto [p, q] : pairs) {
      if (A(p, q) == 0) continue;
      // The rotation J in the (p, q) plane that annihilates A(p, q) (Golub & Van Loan §8.5.2).
      const Real100 theta = (A(q, q) - A(p, p)) / (2 * A(p, q));
      const Real100 t = (theta >= 0 ? 1 : -1) / (abs(theta) + sqrt(theta * theta + 1));
      const Real100 c = 1 / sqrt(t * t + 1);
      const Real100 s = t * c;
      Mat3R100 J = Mat3R100::Identity();
      J(p, p) = c, J(q, q) = c, J(p, q) = s, J(q, p) = -s;
      A = (J.transpose() * A * J).eval();
      A(p, q) = A(q, p) = 0;
      V = (V * J).eval();
    }
  }
  std::array<int, 3> order{0, 1, 2};
  std::ranges::sort(order, [&](int i, int j) { return A(i, i) < A(j, j); });
  ReferenceEigen out;
  for (int k = 0; k < 3; ++k) {
    out.lambda(k) = A(order[k], order[k]);
    out.V.col(k) = V.col(order[k]);
  }
  return out;
}

Mat3R100 exp_by_eigen(const Mat3R100& S) {
  const ReferenceEigen e = reference_eigen(S);
  Vec3R100 exp_lambda;
  for (int k = 0; k < 3; ++k) exp_lambda(k) = exp(e.lambda(k));
  return linalg::congruence(e.V, exp_lambda);
}

Mat3R100 exp_by_taylor(const Mat3R100& S) {
  // Scale so that ‖S/2^s‖_F ≤ 1/2; the series then needs about 80 terms for 10⁻¹⁰⁵.
  const double norm = static_cast<double>(frobenius(require_symmetric(S)));
  const int s = norm > 0.5 ? static_cast<int>(std::ceil(std::log2(norm / 0.5))) : 0;
  const Mat3R100 A = S / pow(Real100(2), s);
  Mat3R100 sum = Mat3R100::Identity();
  Mat3R100 term = Mat3R100::Identity();
  const Real100 negligible("1e-105");
  for (int k = 1; k < 400; ++k) {
    term = (term * A / Real100(k)).eval();
    sum += term;
    if (frobenius(term) < negligible * frobenius(sum)) break;
  }
  for (int i = 0; i < s; ++i) sum = (sum * sum).eval();
  return sum;
}

Mat3R100 to_real100(const Mat3& S) { return S.cast<Real100>(); }

Mat3R100 to_real100(const exact::Mat3Q& S) {
  Mat3R100 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(i, j) = Real100(S(i, j));
  return out;
}

Mat3R50 reference_exp(const Mat3& S) { return exp_by_eigen(to_real100(S)).cast<Real50>(); }

Mat3R50 reference_exp_taylor(const Mat3& S) { return exp_by_taylor(to_real100(S)).cast<Real50>(); }

Vec3R50 reference_eigenvalues(const Mat3& S) { return reference_eigen(to_real100(S)).lambda.cast<Real50>(); }

double relative_error(const Mat3& X, const Mat3R50& E) {
  Real50 diff = 0, norm = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Real50 d = Real50(X(i, j)) - E(i, j);
      diff += d * d;
      norm += E(i, j) * E(i, j);
    }
  }
  return static_cast<double>(sqrt(diff / norm));
}

double eigenvalue_error(const Vec3& x, const Vec3R50& e) {
  if (!x.allFinite()) return NAN;
  Real50 worst = 0, scale = 1;
  for (int i = 0; i < 3; ++i) {
    worst = std::max(worst, Real50(abs(Real50(x(i)) - e(i))));
    scale = std::max(scale, Real50(abs(e(i))));
  }
  return static_cast<double>(worst / scale);
}

}  // namespace affinterp::sym3
