#pragma once
// Why ((1−t)I + tB) is not "good for norm" (thesis Def 2.2.2), as re-verifiable exact numbers: a rational
// direction v with P(v) < 0 < Q(v) (theory/local/goodness.hpp), the time t* ∈ (0, 1) of the dip, and
// ‖A(t)v‖² at t = 0, t*, 1 (the middle value is below both ends).
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <optional>

namespace affinterp::claims::local {

using affinterp::local::Mat2;
using affinterp::local::Vec2;
using exact::Rational;

/// A direction v with the fewest decimal digits where the norm dips, if any (searched on a fine grid).
inline std::optional<Vec2<Rational>> norm_dip_direction(const Mat2<Rational>& B) {
  const affinterp::local::NormForms<Rational> forms(B);
  const Eigen::Matrix2d P = forms.P.unaryExpr([](const Rational& q) { return static_cast<double>(q); });
  const Eigen::Matrix2d Q = forms.Q.unaryExpr([](const Rational& q) { return static_cast<double>(q); });
  double best_margin = 0, best_phi = 0;
  constexpr int directions = 7200;
  for (int k = 0; k < directions; ++k) {
    const double phi = std::numbers::pi * k / directions;
    const Eigen::Vector2d v(std::cos(phi), std::sin(phi));
    const double margin = std::min(-v.dot(P * v), v.dot(Q * v));
    if (margin > best_margin) best_margin = margin, best_phi = phi;
  }
  if (best_margin <= 0) return std::nullopt;
  for (int digits = 0; digits <= 15; ++digits) {
    const double scale = std::pow(10.0, digits);
    const Vec2<Rational> v(
        Rational(static_cast<long long>(std::round(std::cos(best_phi) * scale))) / static_cast<long long>(scale),
        Rational(static_cast<long long>(std::round(std::sin(best_phi) * scale))) / static_cast<long long>(scale));
    if (affinterp::local::norm_dips(B, v)) return v;
  }
  return std::nullopt;
}

inline nlohmann::json norm_witness(const Mat2<Rational>& B) {
  const auto v = norm_dip_direction(B);
  if (!v) return {{"v", nullptr}, {"note", "no rational dip direction found on the search grid"}};
  const Rational t = affinterp::local::norm_dip_time(B, *v);
  const auto norm2 = [&](const Rational& s) {
    const Mat2<Rational> A_s = affinterp::local::scaled(Rational(1) - s, affinterp::local::identity2<Rational>()) +
                               affinterp::local::scaled(s, B);
    return Vec2<Rational>(A_s.lazyProduct(*v)).squaredNorm();
  };
  return {{"v", {exact::to_string((*v)(0)), exact::to_string((*v)(1))}},
          {"v_note", "any nonzero multiple of v; the unit vector v/|v| gives the same monotonicity"},
          {"t", {"0", exact::to_string(t), "1"}},
          {"|A(t)v|^2", {exact::to_string(norm2(0)), exact::to_string(norm2(t)), exact::to_string(norm2(1))}}};
}

}  // namespace affinterp::claims::local
