#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/printed_conditions.hpp"
#include "experiments/claims/local/region_figure.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/svd_homotopy.hpp"
#include "theory/local/svd_norm_goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace affinterp::claims::local::thesis_thm_2_2_3 {
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
// Method: proof for all reals: by Lemma L9 (reports/proofs/LEMMAS.md) A_s is good for norm iff
//   G(t) ≥ 0 on [0, 1] (level G). Sentences in x, y, β decided by QEPCAD B and Z3: printed condition ∧ ¬G-level
//   property (non-empty: its point, shrunk and re-verified, is the counterexample), ¬condition ∧ G(1) ≥ 0 (the
//   property's instance t = 1: empty, so the property implies the condition), and both directions at β = 0 (empty:
//   the printed condition is exact there); under the full size also β = 0 at level D of Def 2.2.2 without L9.
//   Second line: over an (x, y, β) grid, the printed condition against the exact decision of Def 2.2.2
//   (theory/local/svd_norm_goodness.hpp: Lemmas L9 + L12, good iff β²(x−y)²(x+y)² ≤ 4xy(x−1)(y−1), decided
//   exactly for β a rational multiple of π); β = 0, the case the proof computes, is tallied apart. The simplest
//   failing case is re-verified in Real50 from the homotopy itself, at v = e1, e2 and quarter times.
// Sizes: quick (x, y) step 1/2, 12 angles; full step 1/8, 48 angles, and the level-D sentences at β = 0.

using affinterp::local::Mat2;
using affinterp::local::svd_good_for_norm_at_pi_multiple;
using affinterp::local::thm_2_2_3_condition;
using exact::Rational;
using exact::Real50;

/// ‖A_s(t)v‖² in Real50, straight from the homotopy (not from the sampler's formula).
Real50 svd_norm_squared_50(const Real50& x, const Real50& y, const Real50& beta, const Real50& phi, const Real50& t) {
  const affinterp::local::SvdHomotopy<Real50> A{{Real50(0), x, y, beta}};
  const affinterp::local::Vec2<Real50> v(cos(phi), sin(phi));
  return (A(t) * v).squaredNorm();
}

/// Lemma L9's direction: with m = (x − 1, y − 1) of one sign and G(1) < 0, G_1 has an eigenvalue of the
/// other sign; along v = (cos φ, sin φ), φ = ψ − β with ψ its eigenvector's angle, d/dt ‖A_s(t)v‖² has the
/// sign of m at t = 0 and the other at t = 1, so an interior time beats both ends. Times scanned at j/256.
nlohmann::json lemma_l9_witness(const Real50& x, const Real50& y, const Real50& beta) {
  const Real50 m1 = x - 1, m2 = y - 1, a = x, b = y;  // a, b = 1 + t m at t = 1
  const Real50 p = m1 * a, r = m2 * b, q = beta * (b * b - a * a) / 2;
  const Real50 half_gap = sqrt((p - r) * (p - r) / 4 + q * q);
  const Real50 lambda = m1 + m2 >= 0 ? (p + r) / 2 - half_gap : (p + r) / 2 + half_gap;
  const Real50 psi = abs(q) > abs(lambda - p) ? atan2(lambda - p, q) : atan2(q, lambda - r);
  const Real50 phi = psi - beta;
  const Real50 f0 = svd_norm_squared_50(x, y, beta, phi, 0), f1 = svd_norm_squared_50(x, y, beta, phi, 1);
  int best = -1;
  Real50 best_score = 0;
  for (int j = 1; j < 256; ++j) {
    const Real50 f = svd_norm_squared_50(x, y, beta, phi, Real50(j) / 256), score = (f - f0) * (f - f1);
    if (score > best_score) best = j, best_score = score;
  }
  if (best < 0) return nullptr;
  return {{"v", {Real50(cos(phi)).str(30), Real50(sin(phi)).str(30)}},
          {"t", {"0", exact::to_string(Rational(best) / 256), "1"}},
          {"|A_s(t)v|^2 (Real50)",
           {f0.str(30), svd_norm_squared_50(x, y, beta, phi, Real50(best) / 256).str(30), f1.str(30)}}};
}

/// β = kπ/m as a string "k*pi/m" in lowest terms.
std::string angle_name(int k, int m) {
  const int g = std::gcd(k, m);
  if (k == 0) return "0";
  const std::string numerator = k / g == 1 ? "pi" : std::to_string(k / g) + "*pi";
  return m / g == 1 ? numerator : numerator + "/" + std::to_string(m / g);
}

/// The proof: the printed condition against Def 2.2.2 for A_s(t) (Lemma L9), for all real x, y > 0 and β.
ProofPlan proof_plan() {
  const Polynomial x = var("x"), y = var("y"), beta = var("beta"), zero(0);
  const Formula domain = logic::greater(x, 0) && logic::greater(y, 0), condition = thm_2_2_3_formula(x, y);
  ProofPlan plan{
      "D = diag(x, y) with x, y > 0 and the right angle beta real (radians; alpha plays no part)",
      "Lemma L9 (by hand, reports/proofs/LEMMAS.md): A_s(t) = R_{t alpha}((1-t)I + tD)R_{t beta} is good for norm iff "
      "G(t) = 4(x-1)(y-1)(1+t(x-1))(1+t(y-1)) - beta^2 t^2 (x-y)^2 (2+t(x+y-2))^2 >= 0 for all t in [0, 1] (level "
      "G). printed.cond-not-prop.G non-empty refutes the printed condition; printed.prop-not-cond.inst (the "
      "property's instance t = 1, a weakening) empty shows the property implies it; at beta = 0 both directions "
      "empty: the printed condition is exact there (the thesis's proof drops R_{t beta}); beta = 0 also at level D of "
      "Def 2.2.2 for (1-t)I + tD, without Lemma L9 (Lemma L1)",
      {cond_not_prop("printed.", "G", {"x", "y", "beta"}, domain, condition, svd_norm_property(x, y, beta)),
       sentence("printed.prop-not-cond.inst",
                "x, y > 0, beta where G(1) >= 0 (implied by the property) and the printed condition fails",
                {"x", "y", "beta"},
                domain && !condition && logic::greater_equal(svd_norm_G(x, y, beta, Polynomial(1)), 0)),
       cond_not_prop("beta0.", "G", {"x", "y"}, domain, condition, svd_norm_property(x, y, zero)),
       prop_not_cond("beta0.", "G", {"x", "y"}, domain, condition, svd_norm_property(x, y, zero))},
      {}};
  const PolyMat2 D{{{x, zero}, {zero, y}}};
  plan.sentences.push_back(cond_not_prop("beta0.", "D", {"x", "y"}, domain, condition, norm_property(D, "D")));
  plan.sentences.push_back(prop_not_cond("beta0.", "D", {"x", "y"}, domain, condition, norm_property(D, "D")));
  return plan;
}

Real50 real50(const Rational& q) { return Real50(numerator(q)) / Real50(denominator(q)); }

/// The proof's counterexample: printed.cond-not-prop.G's point shrunk while the printed condition holds and the
/// exact decider (Lemmas L9 + L12) says not good; G(1) and an explicit direction (Real50) re-verify it.
nlohmann::json proof_counterexample(const ProofRun& run) {
  const auto fails = [](const logic::Point& p) {
    const Rational &x = p.at("x"), &y = p.at("y"), &beta = p.at("beta");
    return x > 0 && y > 0 && thm_2_2_3_condition(x, y) &&
           !affinterp::local::svd_good_for_norm<Rational>(x, y, beta * beta);
  };
  const auto point = counterexample(run, "printed.cond-not-prop.G", fails, {{{"x", 2}, {"y", 1}, {"beta", 1}}});
  if (!point) return nullptr;
  const Rational &x = point->at("x"), &y = point->at("y"), &beta = point->at("beta");
  return {{"point", exact_point({{"x", x}, {"y", y}, {"beta", beta}})},
          {"printed_condition", true},
          {"G(1) = 4xy(x-1)(y-1) - beta^2(x-y)^2(x+y)^2",
           exact::to_string(affinterp::local::svd_norm_margin<Rational>(x, y, beta * beta))},
          {"witness", lemma_l9_witness(real50(x), real50(y), real50(beta))},
          {"found_by",
           "the deciders' sample point of printed.cond-not-prop.G, shrunk to small rationals; not good by "
           "Lemmas L9 + L12 (G(1) < 0, exact) and along the witness direction (Real50)"}};
}

/// The (x, y, β) grid: x = i/per_unit, y = j/per_unit in (0, 3], β = 2πk/angles in [0, 2π) (the thesis takes
/// α, β ∈ [0, 2π)); the printed condition and the exact property (Lemmas L9 + L12) at each case.
struct Grid {
  int per_unit, angles;
  using Case = std::tuple<int, int, int>;  // (i, j, k)

  Rational x_of(const Case& c) const { return Rational(std::get<0>(c)) / per_unit; }
  Rational y_of(const Case& c) const { return Rational(std::get<1>(c)) / per_unit; }
  Rational beta_over_pi(const Case& c) const { return Rational(2 * std::get<2>(c)) / angles; }
  bool condition(const Case& c) const { return thm_2_2_3_condition(x_of(c), y_of(c)); }
  bool property(const Case& c) const { return svd_good_for_norm_at_pi_multiple(x_of(c), y_of(c), beta_over_pi(c)); }
  /// Simplest first, the usual order x >= y preferred.
  double cost(const Case& c) const {
    return height(x_of(c)) + height(y_of(c)) + height(beta_over_pi(c)) + (x_of(c) < y_of(c) ? 0.5 : 0);
  }
  std::vector<Case> cases() const {
    std::vector<Case> all;
    for (int i = 1; i <= 3 * per_unit; ++i)
      for (int j = 1; j <= 3 * per_unit; ++j)
        for (int k = 0; k < angles; ++k) all.emplace_back(i, j, k);
    return all;
  }
};

/// A witness that |A_s(t)v| is not monotone at (x, y, β): v = e1 or e2 and three quarter times where it rises then
/// falls (Real50), else Lemma L9's witness direction.
nlohmann::json grid_witness(const Real50& x, const Real50& y, const Real50& beta) {
  for (const auto& [phi_name, phi] : {std::pair{"0", Real50(0)}, std::pair{"pi/2", affinterp::local::pi<Real50>() / 2}})
    for (int a = 0; a <= 4; ++a)
      for (int b = a + 1; b <= 4; ++b)
        for (int e = b + 1; e <= 4; ++e) {
          const Real50 fa = svd_norm_squared_50(x, y, beta, phi, Real50(a) / 4),
                       fb = svd_norm_squared_50(x, y, beta, phi, Real50(b) / 4),
                       fe = svd_norm_squared_50(x, y, beta, phi, Real50(e) / 4);
          if ((fb - fa) * (fb - fe) > Real50("1e-30"))
            return {{"v", phi_name == std::string("0") ? nlohmann::json{"1", "0"} : nlohmann::json{"0", "1"}},
                    {"t",
                     {exact::to_string(Rational(a) / 4), exact::to_string(Rational(b) / 4),
                      exact::to_string(Rational(e) / 4)}},
                    {"|A_s(t)v|^2 (Real50)", {fa.str(30), fb.str(30), fe.str(30)}}};
        }
  return lemma_l9_witness(x, y, beta);
}

/// The grid's verdict: confirmed when the printed condition matches the exact decision everywhere; refuted,
/// with the simplest grid case where the condition holds but the norm is not monotone (and its witness), or
/// with the count of good cases the condition misses.
template <typename Tally>
void decide_on_grid(Outcome& outcome, const Grid& grid, const Tally& tally, const Tally& unrotated) {
  if (tally.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary =
        "the printed condition matches the exact decision on all " + std::to_string(tally.cases) + " cases";
    return;
  }
  outcome.verdict = Verdict::refuted;
  if (tally.condition_only.count == 0) {
    outcome.summary =
        std::to_string(tally.property_only.count) + " cases fail the printed condition but are good for norm";
    return;
  }
  const Grid::Case& c = *tally.condition_only.simplest;
  const Real50 x(static_cast<double>(grid.x_of(c))), y(static_cast<double>(grid.y_of(c)));
  const Real50 beta = 2 * affinterp::local::pi<Real50>() * std::get<2>(c) / grid.angles;
  const affinterp::local::Svd<Real50> svd{Real50(0), x, y, beta};
  outcome.summary = std::to_string(tally.condition_only.count) + " of " + std::to_string(tally.cases) +
                    " (x, y, beta) cases satisfy the printed condition but |A_s(t)v| is not monotone for some v; " +
                    std::to_string(tally.property_only.count) + " fail the condition yet are good. At beta = 0 the " +
                    "condition is exact (" + std::to_string(unrotated.disagreements()) + " disagreements of " +
                    std::to_string(unrotated.cases) + "): the proof drops R_{t beta}";
  outcome.counterexample = {
      {"x", exact::to_string(grid.x_of(c))},
      {"y", exact::to_string(grid.y_of(c))},
      {"alpha", "0"},
      {"beta", angle_name(2 * std::get<2>(c), grid.angles)},
      {"A",
       float_matrix(svd.matrix().unaryExpr([](const Real50& a) { return abs(a) < Real50("1e-40") ? Real50(0) : a; }))},
      {"printed_condition", true},
      {"witness", grid_witness(x, y, beta)}};
}

/// The decided proof against the grid (the printed condition exact iff both directions are empty), its
/// counterexample where the condition is not sufficient, and the exact region (atlas.svd.norm).
void add_proof(const ClaimContext& ctx, Outcome& outcome) {
  ProofRun proof = run_proof(ctx, proof_plan());
  if (proof.decided()) {
    const bool printed_exact =
        proof.result("printed.cond-not-prop.G") == "empty" && proof.result("printed.prop-not-cond.inst") == "empty";
    require_agreement(outcome, printed_exact ? Verdict::confirmed : Verdict::refuted);
    if (proof.result("printed.cond-not-prop.G") == "non-empty")
      outcome.counterexample["from_proof"] = proof_counterexample(proof);
  }
  outcome.summary +=
      ". Exact region (atlas.svd.norm, Lemmas L9 + L12): good iff beta^2 (x-y)^2 (x+y)^2 <= 4xy(x-1)(y-1), beta in "
      "radians";
  attach_proof(outcome, std::move(proof));
}

/// Per (x, y): good for every grid β (the theorem's "iff" over all SVDs) against the printed condition.
std::vector<std::string> region_figure(const ClaimContext& ctx, const Grid& grid,
                                       const std::vector<Grid::Case>& cases) {
  std::map<std::pair<int, int>, bool> good_for_all;
  for (const Grid::Case& c : cases) {
    auto [it, fresh] = good_for_all.try_emplace({std::get<0>(c), std::get<1>(c)}, true);
    it->second = it->second && grid.property(c);
  }
  std::vector<plots::RegionPoint> points;
  for (const auto& [ij, good] : good_for_all) {
    const Rational x = Rational(ij.first) / grid.per_unit, y = Rational(ij.second) / grid.per_unit;
    points.push_back({static_cast<double>(x), static_cast<double>(y), thm_2_2_3_condition(x, y), good});
  }
  return draw_region_figure(ctx, "thesis-thm-2.2.3-region",
                            "Thm 2.2.3 (SVD interpolation): printed condition vs good for norm for every grid beta",
                            "x", "y", points, 0.5 / grid.per_unit);
}

Outcome check(const ClaimContext& ctx) {
  const Grid grid{ctx.pick(2, 8), ctx.pick(12, 48)};
  const std::vector<Grid::Case> cases = grid.cases();
  const auto condition = [&](const Grid::Case& c) { return grid.condition(c); };
  const auto property = [&](const Grid::Case& c) { return grid.property(c); };
  const auto cost = [&](const Grid::Case& c) { return grid.cost(c); };
  const auto tally = compare_over(cases, ctx.threads, condition, property, cost);
  std::vector<Grid::Case> unrotated;  // β = 0: the case the thesis's proof actually computes
  for (const Grid::Case& c : cases)
    if (std::get<2>(c) == 0) unrotated.push_back(c);
  const auto unrotated_tally = compare_over(unrotated, ctx.threads, condition, property, cost);

  Outcome outcome;
  outcome.evidence.method =
      "exact decision of Def 2.2.2 for A_s(t) (Lemmas L9 + L12) vs the printed condition over an (x, y, beta) "
      "grid; the shown failure re-verified in Real50 from the homotopy";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.details["reading"] =
      "A_s(t) = R_{t alpha}((1-t)I + tD)R_{t beta} is built from a given SVD (x, y, alpha, beta), x, y > 0, alpha, "
      "beta in "
      "[0, 2pi) as in the thesis; the condition is on x, y only. |A_s(t)v| = |((1-t)I + tD)R_{t beta}v|, so alpha "
      "drops out "
      "but beta does not: the proof's formula for |A_s(t)v|^2 omits R_{t beta}.";
  outcome.evidence.details["decider"] =
      "Lemma L9: good for norm iff G(t) = 4(x-1)(y-1)(1+t(x-1))(1+t(y-1)) - beta^2 t^2 (x-y)^2 (2+t(x+y-2))^2 >= 0 "
      "on [0, 1]; Lemma L12: iff G(1) >= 0, i.e. beta^2 (x-y)^2 (x+y)^2 <= 4xy(x-1)(y-1), beta in radians; decided "
      "exactly against rational bounds on pi (theory/local/svd_norm_goodness.hpp)";
  outcome.evidence.details["grid"] =
      "x, y in (0, 3] step 1/" + std::to_string(grid.per_unit) + "; beta = 2 pi k/" + std::to_string(grid.angles);
  outcome.evidence.details["printed_condition"] = tally.summary();
  outcome.evidence.details["printed_condition_at_beta_0"] = unrotated_tally.summary();
  decide_on_grid(outcome, grid, tally, unrotated_tally);
  add_proof(ctx, outcome);
  if (ctx.draws_figures()) outcome.figures = region_figure(ctx, grid, cases);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_3
