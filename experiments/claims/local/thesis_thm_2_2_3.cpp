#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/region_figure.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/svd_homotopy.hpp"
#include "theory/local/svd_norm_sampling.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace affinterp::claims::local {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.3",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.3",
    .statement = "SVD interpolation R_{tα}((1−t)I + tD)R_{tβ}, D = diag(x, y), is good for norm exactly when x, y are "
                 "both ≥ 1 or both in (0, 1].",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} is built from a given SVD (x, y, α, β), x, y > 0, α, β ∈ [0, 2π) as
//   in the thesis, and the condition is on x, y only. |A_s(t)v| = |((1−t)I + tD)R_{tβ}v|: α drops out, β does not,
//   and the proof's formula for |A_s(t)v|² omits R_{tβ}.
// Method: over an (x, y, β) grid, the printed condition against a sampled decision of Def 2.2.2
//   (theory/local/svd_norm_sampling.hpp: directions × times, a relative tolerance); β = 0, the case the proof
//   computes, is tallied apart. The simplest failing case is re-verified in Real50 from the homotopy itself,
//   first at v = e1, e2 and quarter times.
// Sizes: quick (x, y) step 1/2, 12 angles, 48 directions × 48 times; full step 1/8, 48 angles, 96 × 96.

using affinterp::local::Mat2;
using affinterp::local::SamplingResolution;
using affinterp::local::svd_norm_failure;
using affinterp::local::thm_2_2_3_condition;
using exact::Rational;
using exact::Real50;

/// ‖A_s(t)v‖² in Real50, straight from the homotopy (not from the sampler's formula).
Real50 svd_norm_squared_50(const Real50& x, const Real50& y, const Real50& beta, const Real50& phi, const Real50& t) {
  const affinterp::local::SvdHomotopy<Real50> A{{Real50(0), x, y, beta}};
  const affinterp::local::Vec2<Real50> v(cos(phi), sin(phi));
  return (A(t) * v).squaredNorm();
}

/// β = kπ/m as a string "k*pi/m" in lowest terms.
std::string angle_name(int k, int m) {
  const int g = std::gcd(k, m);
  if (k == 0) return "0";
  const std::string numerator = k / g == 1 ? "pi" : std::to_string(k / g) + "*pi";
  return m / g == 1 ? numerator : numerator + "/" + std::to_string(m / g);
}

Outcome check(const ClaimContext& ctx) {
  // (x, y) = (i, j)/per_unit in (0, 3]; β = 2πk/angles in [0, 2π) (the thesis takes α, β ∈ [0, 2π)).
  const int per_unit = ctx.pick(2, 8), angles = ctx.pick(12, 48);
  const SamplingResolution resolution{ctx.pick<std::size_t>(48, 96), ctx.pick<std::size_t>(48, 96), 1e-9};
  using Case = std::tuple<int, int, int>;  // (i, j, k): x = i/per_unit, y = j/per_unit, β = 2πk/angles
  std::vector<Case> cases;
  for (int i = 1; i <= 3 * per_unit; ++i)
    for (int j = 1; j <= 3 * per_unit; ++j)
      for (int k = 0; k < angles; ++k) cases.emplace_back(i, j, k);
  const auto x_of = [&](const Case& c) { return Rational(std::get<0>(c)) / per_unit; };
  const auto y_of = [&](const Case& c) { return Rational(std::get<1>(c)) / per_unit; };
  const auto beta_of = [&](const Case& c) { return 2 * std::numbers::pi * std::get<2>(c) / angles; };
  const auto condition = [&](const Case& c) { return thm_2_2_3_condition(x_of(c), y_of(c)); };
  const auto property = [&](const Case& c) {
    return !svd_norm_failure(static_cast<double>(x_of(c)), static_cast<double>(y_of(c)), beta_of(c), resolution)
                .has_value();
  };
  const auto cost = [&](const Case& c) {  // simplest first, the usual order x >= y preferred
    return height(x_of(c)) + height(y_of(c)) + height(Rational(2 * std::get<2>(c)) / angles) +
           (x_of(c) < y_of(c) ? 0.5 : 0);
  };
  const auto tally = compare_over(cases, ctx.threads, condition, property, cost);
  std::vector<Case> unrotated;  // β = 0: the case the thesis's proof actually computes
  for (const Case& c : cases)
    if (std::get<2>(c) == 0) unrotated.push_back(c);
  const auto unrotated_tally = compare_over(unrotated, ctx.threads, condition, property, cost);

  Outcome outcome;
  outcome.evidence.method =
      "sampled decision of Def 2.2.2 for A_s(t) vs the printed condition over an (x, y, beta) grid; "
      "failures re-verified in Real50";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.tolerance = resolution.relative_tolerance;
  outcome.evidence.details["reading"] =
      "A_s(t) = R_{t alpha}((1-t)I + tD)R_{t beta} is built from a given SVD (x, y, alpha, beta), x, y > 0, alpha, "
      "beta in "
      "[0, 2pi) as in the thesis; the condition is on x, y only. |A_s(t)v| = |((1-t)I + tD)R_{t beta}v|, so alpha "
      "drops out "
      "but beta does not: the proof's formula for |A_s(t)v|^2 omits R_{t beta}.";
  outcome.evidence.details["resolution"] = {{"directions", resolution.directions},
                                            {"times", resolution.times},
                                            {"relative_tolerance", resolution.relative_tolerance},
                                            {"meaning",
                                             "a direction fails when sampled |A_s(t)v|^2 both rises and falls by more "
                                             "than the tolerance; 'good' = no failing direction at this resolution"}};
  outcome.evidence.details["grid"] =
      "x, y in (0, 3] step 1/" + std::to_string(per_unit) + "; beta = 2 pi k/" + std::to_string(angles);
  outcome.evidence.details["printed_condition"] = tally.summary();
  outcome.evidence.details["printed_condition_at_beta_0"] = unrotated_tally.summary();

  if (tally.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary =
        "the printed condition matches the sampled decision on all " + std::to_string(tally.cases) + " cases";
  } else if (tally.condition_only.count > 0) {
    // Shrink: the simplest failing grid case; then look for a witness at v = e1, e2 and quarter times.
    const Case& c = *tally.condition_only.simplest;
    const Real50 x(static_cast<double>(x_of(c))), y(static_cast<double>(y_of(c)));
    const Real50 beta = 2 * affinterp::local::pi<Real50>() * std::get<2>(c) / angles;
    nlohmann::json witness;
    for (const auto& [phi_name, phi] :
         {std::pair{"0", Real50(0)}, std::pair{"pi/2", affinterp::local::pi<Real50>() / 2}}) {
      for (int a = 0; a <= 4 && witness.is_null(); ++a)
        for (int b = a + 1; b <= 4 && witness.is_null(); ++b)
          for (int e = b + 1; e <= 4 && witness.is_null(); ++e) {
            const Real50 fa = svd_norm_squared_50(x, y, beta, phi, Real50(a) / 4),
                         fb = svd_norm_squared_50(x, y, beta, phi, Real50(b) / 4),
                         fe = svd_norm_squared_50(x, y, beta, phi, Real50(e) / 4);
            if ((fb - fa) * (fb - fe) > Real50("1e-30"))
              witness = {{"v", phi_name == std::string("0") ? nlohmann::json{"1", "0"} : nlohmann::json{"0", "1"}},
                         {"t",
                          {exact::to_string(Rational(a) / 4), exact::to_string(Rational(b) / 4),
                           exact::to_string(Rational(e) / 4)}},
                         {"|A_s(t)v|^2 (Real50)", {fa.str(30), fb.str(30), fe.str(30)}}};
          }
    }
    if (witness.is_null()) {
      const auto w =
          *svd_norm_failure(static_cast<double>(x), static_cast<double>(y), static_cast<double>(beta), resolution);
      const Real50 phi(w.phi);
      witness = {{"v", {Real50(cos(phi)).str(30), Real50(sin(phi)).str(30)}},
                 {"t",
                  {exact::to_string(exact::from_double(w.t_a)), exact::to_string(exact::from_double(w.t_b)),
                   exact::to_string(exact::from_double(w.t_c))}},
                 {"|A_s(t)v|^2 (Real50)",
                  {svd_norm_squared_50(x, y, beta, phi, Real50(w.t_a)).str(30),
                   svd_norm_squared_50(x, y, beta, phi, Real50(w.t_b)).str(30),
                   svd_norm_squared_50(x, y, beta, phi, Real50(w.t_c)).str(30)}}};
    }
    const affinterp::local::Svd<Real50> svd{Real50(0), x, y, beta};
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.condition_only.count) + " of " + std::to_string(tally.cases) +
                      " (x, y, beta) cases satisfy the printed condition but |A_s(t)v| is not monotone for some v; " +
                      std::to_string(tally.property_only.count) +
                      " fail the condition yet sample as good. At beta = 0 the "
                      "condition is exact (" +
                      std::to_string(unrotated_tally.disagreements()) + " disagreements of " +
                      std::to_string(unrotated_tally.cases) + "): the proof drops R_{t beta}";
    outcome.counterexample = {{"x", exact::to_string(x_of(c))},
                              {"y", exact::to_string(y_of(c))},
                              {"alpha", "0"},
                              {"beta", angle_name(2 * std::get<2>(c), angles)},
                              {"A", float_matrix(svd.matrix().unaryExpr(
                                        [](const Real50& a) { return abs(a) < Real50("1e-40") ? Real50(0) : a; }))},
                              {"printed_condition", true},
                              {"witness", witness}};
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary =
        std::to_string(tally.property_only.count) + " cases fail the printed condition but sample as good for norm";
  }
  if (ctx.draws_figures()) {
    // Per (x, y): good for every sampled β (the theorem's "iff" over all SVDs) vs the printed condition.
    std::map<std::pair<int, int>, bool> good_for_all;
    for (const Case& c : cases) {
      auto [it, fresh] = good_for_all.try_emplace({std::get<0>(c), std::get<1>(c)}, true);
      it->second = it->second && property(c);
    }
    std::vector<plots::RegionPoint> points;
    for (const auto& [ij, good] : good_for_all) {
      const Rational x = Rational(ij.first) / per_unit, y = Rational(ij.second) / per_unit;
      points.push_back({static_cast<double>(x), static_cast<double>(y), thm_2_2_3_condition(x, y), good});
    }
    outcome.figures =
        draw_region_figure(ctx, "thesis-thm-2.2.3-region",
                           "Thm 2.2.3 (SVD interpolation): printed condition vs good for norm for every sampled beta",
                           "x", "y", points, 0.5 / per_unit);
  }
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local
