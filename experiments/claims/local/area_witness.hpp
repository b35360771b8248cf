#pragma once
// Why det((1−t)I + tB) is not "good for area" (thesis Def 2.2.1) on [0, 1], as re-verifiable exact
// numbers: the times t = 0, t*, 1 (t* the interior critical point, when there is one) and the values there.
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/matrix2.hpp"

#include <nlohmann/json.hpp>

namespace affinterp::claims::local {

using affinterp::local::Mat2;
using exact::Rational;

inline nlohmann::json area_witness(const Mat2<Rational>& B) {
  const auto det = affinterp::local::blend_determinant(B);
  const auto t_star = affinterp::local::interior_critical_point(det);
  const std::vector<Rational> times = t_star ? std::vector<Rational>{0, *t_star, 1} : std::vector<Rational>{0, 1};
  nlohmann::json t_json = nlohmann::json::array(), det_json = nlohmann::json::array();
  for (const Rational& t : times) t_json.push_back(exact::to_string(t)), det_json.push_back(exact::to_string(det(t)));
  const bool monotone = affinterp::local::monotone_on_unit_interval(det);
  return {
      {"t", t_json},
      {"det((1-t)I + tB)", det_json},
      {"det polynomial [c0, c1, c2]", {exact::to_string(det.c0), exact::to_string(det.c1), exact::to_string(det.c2)}},
      {"fails", monotone ? "positivity" : "monotonicity: an interior extreme at the middle t"}};
}

}  // namespace affinterp::claims::local
