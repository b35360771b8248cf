#include "experiments/claims/sym3/accuracy.hpp"

#include "experiments/claims/values.hpp"
#include "experiments/common/parallel.hpp"
#include "experiments/common/progress.hpp"
#include "experiments/sym3/exp_batch.hpp"
#include "experiments/sym3/families.hpp"
#include "plots/figure.hpp"
#include "theory/sym3/reference.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace affinterp::claims::sym3 {

namespace {

using affinterp::sym3::Family;
using affinterp::sym3::Mat3;
using affinterp::sym3::NamedExpBatch;

constexpr std::string_view kClaimAlgorithm = "thesis-improved-sd";
constexpr std::string_view kOurs = "affinterp";
constexpr std::size_t kQuickPerFamily = 12, kFullPerFamily = 400;

/// The 50-digit reference exp S split into its nearest double and the remainder, so that errors of
/// double results are measured below the double rounding of the reference itself.
struct Reference {
  Mat3 high, low;
};

Reference reference_of(const Mat3& S) {
  const auto exact = affinterp::sym3::reference_exp(S);
  Reference r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r.high(i, j) = static_cast<double>(exact(i, j));
      r.low(i, j) = static_cast<double>(exact(i, j) - r.high(i, j));
    }
  return r;
}

/// ‖E − exp S‖_F / ‖exp S‖_F; +∞ for a non-finite result.
double relative_error(const Mat3& E, const Reference& reference) {
  if (!E.allFinite()) return std::numeric_limits<double>::infinity();
  return ((E - reference.high) - reference.low).norm() / reference.high.norm();
}

double spectral_norm(const Mat3& S) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(S, Eigen::EigenvaluesOnly).eigenvalues().cwiseAbs().maxCoeff();
}

/// The relative errors of every algorithm on every matrix of one family: errors[a][k].
struct FamilySweep {
  const Family* family;
  std::vector<Mat3> S;
  std::vector<Reference> reference;
  std::vector<std::vector<double>> errors;
};

struct Stats {
  double max = 0, p999 = 0;
  std::size_t worst = 0;  ///< index of the worst matrix
};

Stats stats_of(const std::vector<double>& errors) {
  Stats s;
  for (std::size_t k = 0; k < errors.size(); ++k)
    if (!(errors[k] <= s.max)) s.max = errors[k], s.worst = k;
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  s.p999 = sorted[static_cast<std::size_t>(std::ceil(0.999 * sorted.size())) - 1];
  return s;
}

std::string scientific(double x) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific << x;
  return out.str();
}

/// One matrix's evidence: S (rows of doubles and their exact values), eigenvalues, result, reference, error.
nlohmann::json matrix_case(const Mat3& S, const NamedExpBatch& algorithm) {
  Mat3 E;
  algorithm.exp(std::span<const Mat3>(&S, 1), std::span<Mat3>(&E, 1));
  const Reference reference = reference_of(S);
  Eigen::Matrix<exact::Rational, 3, 3> exact_S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) exact_S(i, j) = exact::from_double(S(i, j));
  const Eigen::Vector3d lambda = Eigen::SelfAdjointEigenSolver<Mat3>(S, Eigen::EigenvaluesOnly).eigenvalues();
  return {
      {"S", float_matrix(S)},
      {"S_exact", exact_matrix(exact_S)},
      {"eigenvalues", {lambda[0], lambda[1], lambda[2]}},
      {"algorithm", algorithm.name},
      {"result", float_matrix(E)},
      {"reference", float_matrix(reference.high)},
      {"relative_frobenius_error", relative_error(E, reference)},
  };
}

/// Simple spectra near the thesis's threshold, tried first for a small counterexample: diagonal
/// diag(a, a + g, a + 2g) and diag(a, a + g, a + 1).
std::vector<Mat3> simple_candidates() {
  std::vector<Mat3> candidates;
  for (double g : {2e-6, 1.5e-6, 3e-6, 5e-6, 1e-5, 1.1e-6, 5e-7, 1e-7})
    for (double a : {1.0, 2.0, 0.0}) {
      candidates.push_back(Eigen::Vector3d(a, a + g, a + 2 * g).asDiagonal());
      candidates.push_back(Eigen::Vector3d(a, a + g, a + 1).asDiagonal());
    }
  return candidates;
}

void draw_error_vs_gap(const RunContext& ctx, const std::vector<FamilySweep>& sweeps,
                       const std::vector<NamedExpBatch>& algorithms, Outcome& outcome) {
  // Gap 0 (exact repeats) is drawn at 10⁻¹⁸; errors of exactly 0 at 10⁻¹⁸ (below every rounding error).
  constexpr double floor = 1e-18;
  plots::Table pairs, triples;
  for (std::size_t a = 0; a < algorithms.size(); ++a) {
    for (const auto& sweep : sweeps) {
      if (!sweep.family->gap) continue;
      const bool pair = sweep.family->name.starts_with("pair");
      const double gap = *sweep.family->gap > 0 ? *sweep.family->gap : floor;
      (pair ? pairs : triples).push_back({gap, std::max(stats_of(sweep.errors[a]).max, floor)});
    }
    pairs.push_back({}), pairs.push_back({});
    triples.push_back({}), triples.push_back({});
  }
  std::string names;
  for (const auto& algorithm : algorithms) names += (names.empty() ? "" : " ") + algorithm.name;
  const std::string panel =
      "set logscale xy\n"
      "set format x '10^{%L}'\nset format y '10^{%L}'\n"
      "set xrange [5e-19:1]\nset yrange [5e-19:10]\n"
      "set xlabel 'eigenvalue gap (0 drawn at 10^{-18})'\n"
      "set ylabel 'max relative Frobenius error'\n"
      "set key outside right top\n"
      "set arrow from 1e-6, graph 0 to 1e-6, graph 1 nohead dt 2 lc rgb '#888888'\n"
      "set arrow from graph 0, first 1e-6 to graph 1, first 1e-6 nohead dt 2 lc rgb '#888888'\n";
  const auto plot = [&](const std::string& block) {
    return "plot for [i=0:" + std::to_string(algorithms.size() - 1) + "] $" + block +
           " index i using 1:2 with linespoints pt (i%7)+1 ps 0.8 lc (i%7)+1 title word(names, i+1)\n";
  };
  const auto files = plots::Figure(ctx.figure_stem("sym3-error-vs-gap"))
                         .size(1100, 900)
                         .data("pairs", pairs)
                         .data("triples", triples)
                         .script("names = '" + names + "'\n" + panel +
                                 "set multiplot layout 2,1\n"
                                 "set title 'pairs λ, λ + gap (third eigenvalue free), in [0, 3]'\n" +
                                 plot("pairs") + "set title 'triples λ, λ + gap, λ + 2 gap, in [0, 3]'\n" +
                                 plot("triples") + "unset multiplot\n")
                         .render();
  for (const auto& f : files) outcome.figures.push_back(RunContext::figure_ref(f));
}

}  // namespace

Outcome check_exp_accuracy(const RunContext& ctx) {
  const std::vector<NamedExpBatch> algorithms = affinterp::sym3::exp_variants();
  const auto claimed = std::find_if(algorithms.begin(), algorithms.end(),
                                    [](const auto& a) { return a.name == kClaimAlgorithm; });
  const auto ours = std::find_if(algorithms.begin(), algorithms.end(), [](const auto& a) { return a.name == kOurs; });
  if (claimed == algorithms.end() || ours == algorithms.end()) throw std::logic_error("sym3 algorithm missing");
  const std::size_t claimed_index = claimed - algorithms.begin(), ours_index = ours - algorithms.begin();

  const std::uint64_t seed = ctx.seed_for("thesis.exp.accuracy");
  const std::size_t per_family = ctx.pick(kQuickPerFamily, kFullPerFamily);
  const auto& families = affinterp::sym3::families();

  // Draw, compute the references (the slow part, in parallel), then run every algorithm.
  std::vector<FamilySweep> sweeps;
  for (std::size_t f = 0; f < families.size(); ++f)
    sweeps.push_back({&families[f], families[f].draw(families[f], seed + f, per_family), {}, {}});
  std::vector<std::pair<std::size_t, std::size_t>> cases;
  for (std::size_t f = 0; f < sweeps.size(); ++f)
    for (std::size_t k = 0; k < per_family; ++k) cases.emplace_back(f, k);
  Progress progress("thesis.exp.accuracy references", cases.size());
  const auto chunks = parallel_chunks(cases.size(), ctx.threads, 32, [&](std::size_t begin, std::size_t end) {
    std::vector<Reference> references;
    for (std::size_t c = begin; c < end; ++c) references.push_back(reference_of(sweeps[cases[c].first].S[cases[c].second]));
    progress.advance(end - begin);
    return references;
  });
  {
    std::size_t c = 0;
    for (const auto& chunk : chunks)
      for (const auto& reference : chunk) sweeps[cases[c++].first].reference.push_back(reference);
  }
  for (auto& sweep : sweeps) {
    std::vector<Mat3> E(sweep.S.size());
    for (const auto& algorithm : algorithms) {
      algorithm.exp(sweep.S, E);
      std::vector<double> errors(E.size());
      for (std::size_t k = 0; k < E.size(); ++k) errors[k] = relative_error(E[k], sweep.reference[k]);
      sweep.errors.push_back(std::move(errors));
    }
  }

  // Details per algorithm and family; the claim over the families inside [0, 3]; our target everywhere.
  nlohmann::json per_algorithm = nlohmann::json::object();
  for (std::size_t a = 0; a < algorithms.size(); ++a) {
    nlohmann::json per_family_json = nlohmann::json::object();
    for (const auto& sweep : sweeps) {
      const Stats s = stats_of(sweep.errors[a]);
      per_family_json[sweep.family->name] = {{"max", s.max}, {"p99.9", s.p999}};
    }
    per_algorithm[algorithms[a].name] = per_family_json;
  }
  double claimed_worst = 0, own_worst_ratio = 0;
  const FamilySweep* claimed_worst_sweep = nullptr;
  std::size_t claimed_worst_k = 0;
  std::string own_worst_family;
  for (const auto& sweep : sweeps) {
    if (sweep.family->in_thesis_range) {
      const Stats s = stats_of(sweep.errors[claimed_index]);
      if (!(s.max <= claimed_worst) || !claimed_worst_sweep)
        claimed_worst = s.max, claimed_worst_sweep = &sweep, claimed_worst_k = s.worst;
    }
    for (std::size_t k = 0; k < sweep.S.size(); ++k) {
      const double ratio = sweep.errors[ours_index][k] / (kOwnTarget * std::max(1.0, spectral_norm(sweep.S[k])));
      if (!(ratio <= own_worst_ratio)) own_worst_ratio = ratio, own_worst_family = sweep.family->name;
    }
  }

  Outcome outcome;
  outcome.evidence.method =
      "sweep: relative Frobenius error ‖E − exp S‖_F / ‖exp S‖_F against a 50-digit reference "
      "(theory/sym3/reference.hpp), every algorithm on every family of experiments/sym3/families.hpp";
  outcome.evidence.sample_size = cases.size();
  outcome.evidence.seed = seed;
  outcome.evidence.tolerance = kThesisErrorBound;
  outcome.evidence.worst_deviation = claimed_worst;
  nlohmann::json family_list = nlohmann::json::object();
  for (const auto& family : families)
    family_list[family.name] = {{"description", family.description}, {"in_thesis_range", family.in_thesis_range}};
  outcome.evidence.details = {
      {"reading", "'improved SD' = thesis-improved-sd: Viète eigenvalues (§3.2) and the spectral decomposition "
                  "of §3.1.2 with the printed 10⁻⁶ equality threshold; 'error' = relative Frobenius error; the "
                  "claim is tested on every family whose spectrum lies in [0, 3] (the thesis distribution MᵀM "
                  "reaches 9 and is reported but not part of the claim)"},
      {"matrices_per_family", per_family},
      {"families", family_list},
      {"errors", per_algorithm},
      {"affinterp_target", {{"statement", "relative error ≤ 2·10⁻¹⁵·max(1, ‖S‖₂) on every matrix"},
                            {"worst_error_over_target", own_worst_ratio},
                            {"worst_family", own_worst_family},
                            {"met", own_worst_ratio <= 1}}},
      {"worst_case", matrix_case(claimed_worst_sweep->S[claimed_worst_k], *claimed)},
      {"worst_family", claimed_worst_sweep->family->name},
  };

  if (claimed_worst < kThesisErrorBound) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "improved SD stays below 10⁻⁶ on every family with eigenvalues in [0, 3] (worst " +
                      scientific(claimed_worst) + ", " + claimed_worst_sweep->family->name + ")";
  } else {
    outcome.verdict = Verdict::refuted;
    // Prefer a simple diagonal counterexample when one fails too; otherwise the worst sampled matrix.
    nlohmann::json counterexample = outcome.evidence.details["worst_case"];
    for (const Mat3& S : simple_candidates()) {
      nlohmann::json candidate = matrix_case(S, *claimed);
      if (candidate["relative_frobenius_error"].get<double>() >= kThesisErrorBound) {
        counterexample = std::move(candidate);
        break;
      }
    }
    outcome.counterexample = counterexample;
    outcome.summary = "improved SD exceeds 10⁻⁶ for eigenvalues in [0, 3]: worst relative error " +
                      scientific(claimed_worst) + " on " + claimed_worst_sweep->family->name +
                      "; counterexample error " +
                      scientific(counterexample["relative_frobenius_error"].get<double>());
  }
  if (ctx.draws_figures()) draw_error_vs_gap(ctx, sweeps, algorithms, outcome);
  return outcome;
}

}  // namespace affinterp::claims::sym3
