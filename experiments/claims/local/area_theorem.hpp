#pragma once
// What the "good for area" theorems of thesis §2.2 (Thms 2.2.1, 2.2.2, 2.2.4, 2.2.6) share: the reading of
// Def 2.2.1, the verdict of a printed condition against the exact decision, and the region map.
#include "experiments/claims/context.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/region_figure.hpp"
#include "experiments/claims/outcome.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <functional>
#include <string>
#include <vector>

namespace affinterp::claims::local {

// The names the area theorems are written in.
using affinterp::local::corrected_area_condition;
using affinterp::local::det2;
using affinterp::local::good_for_area;
using affinterp::local::Mat2;
using affinterp::local::thm_2_2_1_condition;
using exact::Rational;

inline const std::string area_reading =
    "Reading: 'good for area' (Def 2.2.1) = det A(t) weakly monotone and > 0 on 0 <= t <= 1, decided "
    "exactly from det((1-t)I + tB) (a quadratic in t recovered from its values at t = 0, 1/2, 1; det R = 1 "
    "removes the rotations of the SVD and polar homotopies). A ranges over GL+(2) (det A > 0).";

/// Fills in the verdict of a printed condition tested against the property, with the corrected area
/// condition tested over the same cases.
template <class Case>
void decide_area_theorem(Outcome& outcome, const ConditionTally<Case>& printed, const ConditionTally<Case>& corrected,
                         const std::string& what) {
  outcome.evidence.details["printed_condition"] = printed.summary();
  outcome.evidence.details["corrected_condition"] = corrected.summary();
  outcome.evidence.sample_size = printed.cases;
  const std::string counts = std::to_string(printed.condition_only.count) + " of " + std::to_string(printed.cases) +
                             " grid cases satisfy the printed condition but are not good for area, " +
                             std::to_string(printed.property_only.count) + " are good but fail it";
  if (printed.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = what + ": the printed condition matches the exact decision on all " +
                      std::to_string(printed.cases) + " grid cases";
  } else if (corrected.disagreements() == 0) {
    outcome.verdict = Verdict::corrected;
    outcome.summary =
        what + ": printed condition fails (" + counts + "); the corrected condition matches on every case";
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary = what + ": printed condition fails (" + counts + "), and so does the stated correction";
  }
}

/// The region map of an area theorem in the (first, second) plane of `coordinates(case)`.
template <class Case, class Coordinates, class Condition>
std::vector<std::string> draw_area_map(const RunSettings& ctx, const std::string& name, const std::string& title,
                                       const std::string& x_label, const std::string& y_label,
                                       const std::vector<Case>& cases, Coordinates coordinates, Condition condition,
                                       std::function<Mat2<Rational>(const Case&)> B_of, const Rational& step) {
  std::vector<plots::RegionPoint> points;
  for (const Case& c : cases) {
    const auto [x, y] = coordinates(c);
    points.push_back({x, y, condition(c), good_for_area(B_of(c))});
  }
  return draw_region_figure(ctx, name, title, x_label, y_label, points, static_cast<double>(step) / 2);
}

}  // namespace affinterp::claims::local
