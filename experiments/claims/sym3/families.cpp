#include "experiments/claims/sym3/families.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace affinterp::sym3 {

Mat3 random_rotation(Rng& rng) {
  Eigen::Vector4d q;
  do {
    for (int i = 0; i < 4; ++i) q(i) = rng.uniform(-1.0, 1.0);
  } while (q.squaredNorm() > 1.0 || q.squaredNorm() < 1e-4);  // uniform in the ball, then normalised
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

Mat3 with_eigenvalues(Rng& rng, const Vec3& lambda) {
  const Mat3 Q = random_rotation(rng);
  const Mat3 S = Q * lambda.asDiagonal() * Q.transpose();
  return 0.5 * (S + S.transpose());
}

namespace {

/// Thesis §3.4: S = MᵀM with the entries of M uniform in [−1, 1].
Mat3 thesis(Rng& rng) {
  Mat3 M;
  for (int i = 0; i < 9; ++i) M.data()[i] = rng.uniform(-1.0, 1.0);
  return M.transpose() * M;
}

/// Eigenvalues uniform in [0, 3] (the range of thesis §3.4's accuracy statement).
Mat3 spread(Rng& rng) {
  return with_eigenvalues(rng, Vec3(rng.uniform(0, 3), rng.uniform(0, 3), rng.uniform(0, 3)));
}

/// A pair (or, one time in four, a triple) of eigenvalues 10⁻ᵏ apart, k uniform in 1..16, in [0, 3].
Mat3 clustered(Rng& rng) {
  const double gap = std::pow(10.0, -static_cast<double>(rng.integer(1, 16)));
  const double a = rng.uniform(0, 3);
  const bool triple = rng.integer(0, 3) == 0;
  return with_eigenvalues(rng, Vec3(a, a + gap, triple ? a + 2 * gap : rng.uniform(0, 3)));
}

/// Exactly repeated eigenvalues: [[b+c, 0, 0], [0, b, c], [0, c, b]] (eigenvalues b+c, b+c, b−c) with
/// its coordinates permuted, or aI; b, c, a multiples of 1/64 so that the matrix is exact.
Mat3 repeated(Rng& rng) {
  const double a = rng.integer(-192, 192) / 64.0;
  if (rng.integer(0, 3) == 0) return a * Mat3::Identity();
  const double b = rng.integer(-128, 128) / 64.0, c = rng.integer(1, 128) / 64.0;
  Mat3 S;
  S << b + c, 0, 0, 0, b, c, 0, c, b;
  std::array<int, 3> p{0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(p[i], p[rng.integer(0, i)]);
  Mat3 P = Mat3::Zero();
  for (int i = 0; i < 3; ++i) P(i, p[i]) = 1;
  return P * S * P.transpose();
}

/// Eigenvalues with ratio 10¹²: s·(±a·10⁻¹², ±b·10⁻⁶, ±c), a, b, c in [1, 2), s = 10^u, u in [−3, 2].
Mat3 wide(Rng& rng) {
  const double s = std::pow(10.0, rng.uniform(-3, 2));
  auto sign = [&] { return rng.integer(0, 1) ? 1.0 : -1.0; };
  return with_eigenvalues(rng, s * Vec3(sign() * rng.uniform(1, 2) * 1e-12, sign() * rng.uniform(1, 2) * 1e-6,
                                        sign() * rng.uniform(1, 2)));
}

/// Eigenvalues uniform in [−700, 700] (exp stays finite in double).
Mat3 large(Rng& rng) {
  return with_eigenvalues(rng, Vec3(rng.uniform(-700, 700), rng.uniform(-700, 700), rng.uniform(-700, 700)));
}

/// Diagonal entries in [−5, 5]; off-diagonal entries zero or 10⁻¹⁰-small.
Mat3 near_diagonal(Rng& rng) {
  Mat3 S = Mat3::Zero();
  for (int i = 0; i < 3; ++i) S(i, i) = rng.uniform(-5, 5);
  if (rng.integer(0, 1)) {
    S(0, 1) = S(1, 0) = 1e-10 * rng.uniform(-1, 1);
    S(0, 2) = S(2, 0) = 1e-10 * rng.uniform(-1, 1);
    S(1, 2) = S(2, 1) = 1e-10 * rng.uniform(-1, 1);
  }
  return S;
}

/// The zero matrix, or a matrix of entries below 10⁻¹⁵⁰ (underflow of squares).
Mat3 zero(Rng& rng) {
  if (rng.integer(0, 1)) return Mat3::Zero();
  Mat3 M;
  for (int i = 0; i < 9; ++i) M.data()[i] = 1e-160 * rng.uniform(-1, 1);
  return M + M.transpose();
}

constexpr std::array catalogue{
    Family{"thesis", "S = MᵀM, M uniform in [−1, 1] (thesis §3.4)", thesis},
    Family{"spread-0-3", "eigenvalues uniform in [0, 3]", spread},
    Family{"clustered", "two or three eigenvalues 10⁻¹ … 10⁻¹⁶ apart", clustered},
    Family{"repeated", "exactly repeated eigenvalues (double or triple)", repeated},
    Family{"wide", "eigenvalue magnitudes spanning 10¹²", wide},
    Family{"large", "eigenvalues in [−700, 700]", large},
    Family{"near-diagonal", "diagonal or with 10⁻¹⁰ off-diagonal entries", near_diagonal},
    Family{"zero", "zero or entries below 10⁻¹⁵⁰", zero},
};

}  // namespace

std::span<const Family> families() { return catalogue; }

const Family* find_family(std::string_view name) {
  const auto it = std::ranges::find(catalogue, name, &Family::name);
  return it == catalogue.end() ? nullptr : &*it;
}

}  // namespace affinterp::sym3
