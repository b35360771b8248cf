#pragma once
// What the "good for area" theorems of thesis §2.2 (Thms 2.2.1, 2.2.2, 2.2.4, 2.2.6) share: the reading of
// Def 2.2.1, the printed condition and its correction tallied against the exact decision, the verdict, and the
// region map.
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

/// Thm 2.2.1's printed condition on tr B and det B (Thms 2.2.2 and 2.2.4 put tr D and tr S for tr A).
inline bool printed_area_condition(const Mat2<Rational>& B) {
  return thm_2_2_1_condition<Rational>(B.trace(), det2(B));
}

/// The printed condition and its correction, each tallied against the exact decision of Def 2.2.1.
template <class Case>
struct AreaTallies {
  ConditionTally<Case> printed, corrected;
};

/// Both conditions over every case, each on the B = B_of(case) of the blend (1−t)I + tB.
template <class Case, class BOf, class Cost>
AreaTallies<Case> tally_area_conditions(const std::vector<Case>& cases, unsigned threads, BOf B_of, Cost cost) {
  const auto property = [&](const Case& c) { return good_for_area(B_of(c)); };
  const auto corrected = [&](const Case& c) {
    const Mat2<Rational> B = B_of(c);
    return corrected_area_condition<Rational>(B.trace(), det2(B));
  };
  return {compare_over(
              cases, threads, [&](const Case& c) { return printed_area_condition(B_of(c)); }, property, cost),
          compare_over(cases, threads, corrected, property, cost)};
}

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

/// The region map of an area theorem, the printed condition against good for area, in the (first, second)
/// plane of `coordinates(case)`.
template <class Case, class Coordinates>
std::vector<std::string> draw_area_map(const RunSettings& ctx, const std::string& name, const std::string& title,
                                       const std::string& x_label, const std::string& y_label,
                                       const std::vector<Case>& cases, Coordinates coordinates,
                                       std::function<Mat2<Rational>(const Case&)> B_of, const Rational& step) {
  std::vector<plots::RegionPoint> points;
  for (const Case& c : cases) {
    const auto [x, y] = coordinates(c);
    const Mat2<Rational> B = B_of(c);
    points.push_back({x, y, printed_area_condition(B), good_for_area(B)});
  }
  return draw_region_figure(ctx, name, title, x_label, y_label, points, static_cast<double>(step) / 2);
}

}  // namespace affinterp::claims::local
