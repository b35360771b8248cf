// thesis Thm 2.2.3 (SVD interpolation good for norm) and Thm 2.2.5 (polar interpolation good for norm):
// the printed conditions against independent decisions of Def 2.2.2, exact for the polar interpolation
// (theory/local/goodness.hpp), sampled and re-verified in Real50 for the SVD one
// (theory/local/svd_norm_sampling.hpp).
#include "experiments/claims/local/checks.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/norm_witness.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "plots/region_map.hpp"
#include "theory/local/svd_homotopy.hpp"
#include "theory/local/svd_norm_sampling.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <map>
#include <numbers>
#include <tuple>

namespace affinterp::claims::local {
namespace {

using affinterp::local::good_for_norm;
using affinterp::local::SamplingResolution;
using affinterp::local::svd_norm_failure;
using affinterp::local::thm_2_2_3_condition;
using affinterp::local::thm_2_2_5_condition;
using exact::Real50;

std::vector<std::string> figure_files(const std::string& name) {
  return {RunContext::figure_ref(name + ".png"), RunContext::figure_ref(name + ".svg")};
}

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

}  // namespace

Outcome check_thm_2_2_5(const RunContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 16);
  using Case = std::tuple<Rational, Rational, Rational>;  // S = [[x, h], [h, y]]
  std::vector<Case> cases;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, 4, step))
      for (const Rational& h : grid(-4, 4, step))
        if (x * y > h * h) cases.emplace_back(x, y, h);
  const auto S_of = [](const Case& c) {
    Mat2<Rational> S;
    S << std::get<0>(c), std::get<2>(c), std::get<2>(c), std::get<1>(c);
    return S;
  };
  const auto condition = [](const Case& c) { return thm_2_2_5_condition(std::get<0>(c), std::get<1>(c), std::get<2>(c)); };
  const auto property = [&](const Case& c) { return good_for_norm(S_of(c)); };
  const auto cost = [](const Case& c) { return height(std::get<0>(c)) + height(std::get<1>(c)) + height(std::get<2>(c)); };
  const auto tally = compare_over(cases, ctx.threads, condition, property, cost);

  Outcome outcome;
  outcome.evidence.method = "exact rational decision of Def 2.2.2 for A_p(t) vs the printed condition over an (x, y, h) grid";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.details["reading"] =
      "'good for norm' (Def 2.2.2) = |A_p(t)v| weakly monotone on [0, 1] for every unit v; |A_p(t)v| = |((1-t)I + tS)v| "
      "(R_{t gamma} is orthogonal). Decided exactly per S: fails iff some v has P(v) < 0 < Q(v), P = S - I, "
      "Q = (S - I) + (S - I)^2, certified by Dines' theorem (see theory/local/goodness.hpp).";
  outcome.evidence.details["grid"] = "x, y in (0, 4], h in [-4, 4], xy > h^2, step " + exact::to_string(step);
  outcome.evidence.details["printed_condition"] = tally.summary();
  if (tally.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "the printed condition matches the exact decision on all " + std::to_string(tally.cases) +
                      " grid cases (it says: both eigenvalues of S >= 1, or both <= 1)";
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.condition_only.count) + " cases satisfy the printed condition but are not good for norm, " +
                      std::to_string(tally.property_only.count) + " are good but fail it (of " + std::to_string(tally.cases) + ")";
    const Case& c = tally.condition_only.simplest ? *tally.condition_only.simplest : *tally.property_only.simplest;
    outcome.counterexample = {{"x", exact::to_string(std::get<0>(c))}, {"y", exact::to_string(std::get<1>(c))},
                              {"h", exact::to_string(std::get<2>(c))}, {"printed_condition", condition(c)},
                              {"good_for_norm", property(c)},          {"witness", norm_witness(S_of(c))}};
  }
  if (ctx.draws_figures()) {
    const std::string name = "thesis-thm-2.2.5-region";
    std::vector<plots::RegionPoint> points;
    for (const Case& c : cases)
      if (std::get<2>(c) == Rational(1) / 2)
        points.push_back({static_cast<double>(std::get<0>(c)), static_cast<double>(std::get<1>(c)), condition(c), property(c)});
    plots::draw_region_map(ctx.figure_stem(name), "Thm 2.2.5 (polar interpolation), slice h = 1/2: printed condition vs good for norm",
                           "x", "y", points, static_cast<double>(step) / 2, static_cast<double>(step) / 2);
    outcome.figures = figure_files(name);
  }
  return outcome;
}

Outcome check_thm_2_2_3(const RunContext& ctx) {
  // (x, y) = (i, j)/8 in (0, 3]; β = kπ/24 in [0, 2π) (the thesis takes α, β ∈ [0, 2π)); α drops out.
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
    return !svd_norm_failure(static_cast<double>(x_of(c)), static_cast<double>(y_of(c)), beta_of(c), resolution).has_value();
  };
  const auto cost = [&](const Case& c) {  // simplest first, the usual order x >= y preferred
    return height(x_of(c)) + height(y_of(c)) + height(Rational(2 * std::get<2>(c)) / angles) + (x_of(c) < y_of(c) ? 0.5 : 0);
  };
  const auto tally = compare_over(cases, ctx.threads, condition, property, cost);
  std::vector<Case> unrotated;  // β = 0: the case the thesis's proof actually computes
  for (const Case& c : cases)
    if (std::get<2>(c) == 0) unrotated.push_back(c);
  const auto unrotated_tally = compare_over(unrotated, ctx.threads, condition, property, cost);

  Outcome outcome;
  outcome.evidence.method = "sampled decision of Def 2.2.2 for A_s(t) vs the printed condition over an (x, y, beta) grid; "
                            "failures re-verified in Real50";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.tolerance = resolution.relative_tolerance;
  outcome.evidence.details["reading"] =
      "A_s(t) = R_{t alpha}((1-t)I + tD)R_{t beta} is built from a given SVD (x, y, alpha, beta), x, y > 0, alpha, beta in "
      "[0, 2pi) as in the thesis; the condition is on x, y only. |A_s(t)v| = |((1-t)I + tD)R_{t beta}v|, so alpha drops out "
      "but beta does not: the proof's formula for |A_s(t)v|^2 omits R_{t beta}.";
  outcome.evidence.details["resolution"] = {{"directions", resolution.directions}, {"times", resolution.times},
                                            {"relative_tolerance", resolution.relative_tolerance},
                                            {"meaning", "a direction fails when sampled |A_s(t)v|^2 both rises and falls by more "
                                                        "than the tolerance; 'good' = no failing direction at this resolution"}};
  outcome.evidence.details["grid"] = "x, y in (0, 3] step 1/" + std::to_string(per_unit) + "; beta = 2 pi k/" + std::to_string(angles);
  outcome.evidence.details["printed_condition"] = tally.summary();
  outcome.evidence.details["printed_condition_at_beta_0"] = unrotated_tally.summary();

  if (tally.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "the printed condition matches the sampled decision on all " + std::to_string(tally.cases) + " cases";
  } else if (tally.condition_only.count > 0) {
    // Shrink: the simplest failing grid case; then look for a witness at v = e1, e2 and quarter times.
    const Case& c = *tally.condition_only.simplest;
    const Real50 x(static_cast<double>(x_of(c))), y(static_cast<double>(y_of(c)));
    const Real50 beta = 2 * affinterp::local::pi<Real50>() * std::get<2>(c) / angles;
    nlohmann::json witness;
    for (const auto& [phi_name, phi] : {std::pair{"0", Real50(0)}, std::pair{"pi/2", affinterp::local::pi<Real50>() / 2}}) {
      for (int a = 0; a <= 4 && witness.is_null(); ++a)
        for (int b = a + 1; b <= 4 && witness.is_null(); ++b)
          for (int e = b + 1; e <= 4 && witness.is_null(); ++e) {
            const Real50 fa = svd_norm_squared_50(x, y, beta, phi, Real50(a) / 4), fb = svd_norm_squared_50(x, y, beta, phi, Real50(b) / 4),
                         fe = svd_norm_squared_50(x, y, beta, phi, Real50(e) / 4);
            if ((fb - fa) * (fb - fe) > Real50("1e-30"))
              witness = {{"v", phi_name == std::string("0") ? nlohmann::json{"1", "0"} : nlohmann::json{"0", "1"}},
                         {"t", {exact::to_string(Rational(a) / 4), exact::to_string(Rational(b) / 4), exact::to_string(Rational(e) / 4)}},
                         {"|A_s(t)v|^2 (Real50)", {fa.str(30), fb.str(30), fe.str(30)}}};
          }
    }
    if (witness.is_null()) {
      const auto w = *svd_norm_failure(static_cast<double>(x), static_cast<double>(y), static_cast<double>(beta), resolution);
      const Real50 phi(w.phi);
      witness = {{"v", {Real50(cos(phi)).str(30), Real50(sin(phi)).str(30)}},
                 {"t", {exact::to_string(exact::from_double(w.t_a)), exact::to_string(exact::from_double(w.t_b)),
                        exact::to_string(exact::from_double(w.t_c))}},
                 {"|A_s(t)v|^2 (Real50)", {svd_norm_squared_50(x, y, beta, phi, Real50(w.t_a)).str(30),
                                           svd_norm_squared_50(x, y, beta, phi, Real50(w.t_b)).str(30),
                                           svd_norm_squared_50(x, y, beta, phi, Real50(w.t_c)).str(30)}}};
    }
    const affinterp::local::Svd<Real50> svd{Real50(0), x, y, beta};
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.condition_only.count) + " of " + std::to_string(tally.cases) +
                      " (x, y, beta) cases satisfy the printed condition but |A_s(t)v| is not monotone for some v; " +
                      std::to_string(tally.property_only.count) + " fail the condition yet sample as good. At beta = 0 the "
                      "condition is exact (" + std::to_string(unrotated_tally.disagreements()) + " disagreements of " +
                      std::to_string(unrotated_tally.cases) + "): the proof drops R_{t beta}";
    outcome.counterexample = {{"x", exact::to_string(x_of(c))},
                              {"y", exact::to_string(y_of(c))},
                              {"alpha", "0"},
                              {"beta", angle_name(2 * std::get<2>(c), angles)},
                              {"A", float_matrix(svd.matrix().unaryExpr([](const Real50& a) { return abs(a) < Real50("1e-40") ? Real50(0) : a; }))},
                              {"printed_condition", true},
                              {"witness", witness}};
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.property_only.count) + " cases fail the printed condition but sample as good for norm";
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
    const std::string name = "thesis-thm-2.2.3-region";
    plots::draw_region_map(ctx.figure_stem(name), "Thm 2.2.3 (SVD interpolation): printed condition vs good for norm for every sampled beta",
                           "x", "y", points, 0.5 / per_unit, 0.5 / per_unit);
    outcome.figures = figure_files(name);
  }
  return outcome;
}

}  // namespace affinterp::claims::local
