#pragma once
// Balls: real numbers known to lie within a radius of a midpoint, the currency of affinterp::certified.
// The high-precision midpoints stay inside (Arb, not exposed here); callers read doubles, rigorous radii
// and decimal strings.
#include <memory>
#include <string>

namespace affinterp::certified {

/// A real number x known to satisfy |x − mid| ≤ rad: mid is a double and rad, rounded up, includes the
/// rounding of the exact midpoint to mid. mid may be ±∞ (with rad = 0) for an infinite error.
struct Ball {
  double mid = 0;
  double rad = 0;
  /// Bounds rounded outward.
  double lower() const;
  double upper() const;
  bool contains(double x) const { return lower() <= x && x <= upper(); }
};

/// A rows × cols array of balls (a 3×3 matrix, or 3 eigenvalues as 3×1) whose midpoints keep the
/// working precision. Cheap to copy (shared, immutable).
class Balls {
 public:
  struct Impl;
  Balls();
  explicit Balls(std::shared_ptr<const Impl> impl);

  int rows() const;
  int cols() const;
  /// The entry as a double ball: mid rounded to nearest, rad including that rounding.
  Ball entry(int i, int j = 0) const;
  /// The nearest double to the exact midpoint.
  double mid(int i, int j = 0) const;
  /// The radius about the exact midpoint (rounded up); +∞ where nothing is known.
  double radius(int i, int j = 0) const;
  double max_radius() const;
  /// An upper bound of ‖R‖_F, R the matrix of radii: the true matrix lies within this Frobenius distance
  /// of the midpoint matrix.
  double frobenius_radius() const;
  /// The Frobenius norm of the (true) matrix, as a ball.
  Ball frobenius_norm() const;
  /// frobenius_radius() / (lower bound of the Frobenius norm): the relative width of the enclosure
  /// (+∞ when the norm may be 0 and the radius is not; 0 for an exact matrix).
  double relative_radius() const;
  /// The exact midpoint in decimal with `digits` significant digits (e.g. to read it into a
  /// Boost.Multiprecision number).
  std::string mid_string(int i, int j = 0, int digits = 40) const;
  /// Arb's "mid +/- rad" rendering with `digits` digits.
  std::string to_string(int i, int j = 0, int digits = 20) const;
  /// Whether every entry is finite (no [± ∞] ball).
  bool finite() const;

  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace affinterp::certified
