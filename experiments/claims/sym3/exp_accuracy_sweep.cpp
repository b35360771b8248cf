#include "experiments/claims/sym3/exp_accuracy_sweep.hpp"

#include "experiments/inputs/sym3/affinelib_exp_sym.hpp"
#include "experiments/support/parallel.hpp"
#include "experiments/support/progress.hpp"
#include "theory/sym3/reference.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace affinterp::claims::sym3 {

namespace {

/// An upper bound of ‖radii‖_F / ‖exp S‖_F that holds where ‖exp S‖_F exceeds the largest double too
/// (‖exp S‖_F ≥ every |entry|).
double relative_radius(const certified::Balls& F) {
  double largest = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(F.mid(i, j)) - F.radius(i, j));
  return largest > 0 ? F.frobenius_radius() / largest : INFINITY;
}

/// The 50-digit Boost reference against Arb's ball: how far outside the ball it lies, relative to
/// ‖exp S‖_F (≤ 0: inside). The Boost reference's own error is about 10⁻⁴⁸ of ‖exp S‖_F.
double boost_outside_ball(const Mat3& S, const certified::Balls& F) {
  const affinterp::sym3::Mat3R50 reference = affinterp::sym3::reference_exp(S);
  double worst = -INFINITY;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const exact::Real50 distance = abs(reference(i, j) - exact::Real50(F.mid_string(i, j, 60)));
      worst = std::max(worst, static_cast<double>(distance) - F.radius(i, j));
    }
  return worst / F.frobenius_norm().lower();
}

/// One matrix's certified exp S, with the Boost cross-check where it was made.
struct Certified {
  CertifiedTruth truth;
  double boost_outside = -INFINITY;  ///< boost_outside_ball, where cross-checked
  bool cross_checked = false;
};

/// Adds one matrix's reference to the summary.
void summarise(const Certified& one, const std::string& family, ReferenceSummary& r) {
  ++r.status[one.truth.exp.status == certified::Status::certified   ? "certified"
             : one.truth.exp.status == certified::Status::overflows ? "overflows"
                                                                    : "too_wide"];
  if (one.truth.exp.status == certified::Status::certified) {
    // Relative radius where ‖exp S‖_F is a normal double; absolute below (where Arb certifies the
    // entries to the double range's own resolution).
    const certified::Balls& F = one.truth.exp.value;
    if (F.frobenius_norm().mid >= std::numeric_limits<double>::min()) {
      if (!(relative_radius(F) <= r.max_relative_radius))
        r.max_relative_radius = relative_radius(F), r.max_radius_family = family;
    } else {
      ++r.below_normal;
      r.max_absolute_radius_below_normal = std::max(r.max_absolute_radius_below_normal, F.frobenius_radius());
    }
  }
  if (!one.cross_checked) return;
  ++r.cross_checked;
  r.outside += one.boost_outside > 1e-45;  // beyond the Boost reference's own 50-digit error
  r.worst_outside = std::max(r.worst_outside, one.boost_outside);
}

}  // namespace

std::vector<NamedExpBatch> algorithms_and_peers() {
  std::vector<NamedExpBatch> all = affinterp::sym3::exp_variants();
  all.push_back({"affinelib-expsym", affinterp::sym3::elementwise(affinterp::sym3::exp_affinelib)});
  return all;
}

AccuracySweep sweep_accuracy(const ClaimContext& ctx, const std::vector<NamedExpBatch>& algorithms,
                             std::size_t per_family, std::size_t cross_checks) {
  const auto& families = affinterp::sym3::families();
  // Draw, certify exp S (the slow part, in parallel) with the Boost cross-checks, then run every algorithm.
  AccuracySweep sweep;
  for (std::size_t f = 0; f < families.size(); ++f)
    sweep.families.push_back({&families[f], families[f].draw(families[f], ctx.seed + f, per_family), {}, {}, {}});
  std::vector<std::pair<std::size_t, std::size_t>> cases;
  for (std::size_t f = 0; f < sweep.families.size(); ++f)
    for (std::size_t k = 0; k < per_family; ++k) cases.emplace_back(f, k);
  sweep.matrices = cases.size();
  Progress progress(std::string(ctx.claim_id) + " certified references", cases.size());
  const auto chunks = parallel_chunks(cases.size(), ctx.threads, 32, [&](std::size_t begin, std::size_t end) {
    std::vector<Certified> out;
    for (std::size_t c = begin; c < end; ++c) {
      const auto [f, k] = cases[c];
      const Mat3& S = sweep.families[f].S[k];
      Certified one{certified_truth(S)};
      if (k < cross_checks && !sweep.families[f].family->whole_double_range &&
          one.truth.exp.status == certified::Status::certified)
        one.boost_outside = boost_outside_ball(S, one.truth.exp.value), one.cross_checked = true;
      out.push_back(std::move(one));
    }
    progress.advance(end - begin);
    return out;
  });
  std::size_t c = 0;
  for (const auto& chunk : chunks)
    for (const auto& one : chunk) {
      FamilySweep& family = sweep.families[cases[c++].first];
      family.truth.push_back(one.truth);
      summarise(one, family.family->name, sweep.references);
    }
  for (auto& family : sweep.families)
    for (const auto& algorithm : algorithms) {
      std::vector<Mat3> E(family.S.size());
      algorithm.exp(family.S, E);
      std::vector<Score> scores(E.size());
      for (std::size_t k = 0; k < E.size(); ++k) scores[k] = score(E[k], family.truth[k]);
      family.scores.push_back(std::move(scores));
      family.results.push_back(std::move(E));
    }
  return sweep;
}

Stats stats_of(const FamilySweep& sweep, std::size_t algorithm) {
  Stats s;
  std::vector<double> counted;
  const auto& scores = sweep.scores[algorithm];
  for (std::size_t k = 0; k < scores.size(); ++k) {
    const Score& score = scores[k];
    ++s.tally[score.judgement];
    if (score.judgement == Judgement::error_not_certified)
      s.max_excluded_upper = std::max(s.max_excluded_upper, score.error_upper);
    if (score.judgement != Judgement::certified && score.judgement != Judgement::non_finite) continue;
    counted.push_back(score.error);
    if (!(score.error <= s.max)) s.max = score.error, s.worst = k;
  }
  s.counted = counted.size();
  if (!counted.empty()) {
    std::sort(counted.begin(), counted.end());
    s.p999 = counted[static_cast<std::size_t>(std::ceil(0.999 * counted.size())) - 1];
  }
  return s;
}

std::size_t tally(const Stats& s, Judgement j) { return s.tally.contains(j) ? s.tally.at(j) : 0; }

Worst worst_in_thesis_range(const std::vector<FamilySweep>& sweeps, std::size_t algorithm) {
  Worst worst;
  for (const auto& sweep : sweeps) {
    if (!sweep.family->in_thesis_range) continue;
    const Stats s = stats_of(sweep, algorithm);
    if (!worst.sweep || !(s.max <= worst.error)) worst = {s.max, &sweep, s.worst};
  }
  return worst;
}

}  // namespace affinterp::claims::sym3
