#include "experiments/measurements/scale_targets.hpp"

#include "experiments/claims/speed_verdict.hpp"
#include "theory/global/sparse_factor.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <tuple>

namespace affinterp::measurements {
namespace {

std::string ms(const std::optional<double>& value) {
  if (!value) return "?";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f ms", *value);
  return text;
}

std::string times(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f×", x);
  return text;
}

/// How many times faster a frame of a batch of 8 is than one frame alone at `row`'s size (NaN: not measured).
double batch_gain(const ScaleRow& row) {
  return row.frame_R.value && row.batch_R.value ? *row.frame_R.value / *row.batch_R.value : std::nan("");
}

/// The spread of a quotient a / b of two spreads: over every pairing of their runs.
std::optional<Interval> quotient_spread(const std::optional<Interval>& a, const std::optional<Interval>& b) {
  if (!a || !b) return std::nullopt;
  return Interval{a->lo / b->hi, a->hi / b->lo};
}

/// A target at `row`'s size, the rows of the engine's back-end there, and what the causes quote of them.
struct AtSize {
  const EngineScale& scale;
  std::size_t r;             ///< the row of scale.rows
  std::string back_end;      ///< the engine's back-end at that size
  const BackEndRow* parts;   ///< its row at that size; null when it did not run there
  const BackEnd* of_engine;  ///< the back-end itself; null when it did not run
  const ScaleRow& row() const { return scale.rows[r]; }
  std::optional<double> part(Cost BackEndRow::*cost) const { return parts ? (parts->*cost).cpu_ms : std::nullopt; }
};

AtSize at_size(const EngineScale& scale, std::size_t r) {
  // At 1M triangles (≥ 500k vertices) the engine factors on CHOLMOD when built with it: above both switches.
  AtSize at{scale, r, global::has_cholmod() ? "cholmod" : "simplicial", nullptr, nullptr};
  for (const BackEnd& b : scale.back_ends)
    if (b.name == at.back_end) {
      at.of_engine = &b;
      for (const BackEndRow& row : b.rows)
        if (row.triangles == scale.rows[r].triangles) at.parts = &row;
    }
  return at;
}

/// Why E^R's batched frame grows as it does from the size before: the factorisation's own exponent, the batch's
/// gain at both sizes, and the switch of back-end between them.
std::string growth_cause(const AtSize& at) {
  const std::optional<double> p = at.of_engine ? at.of_engine->exponents.factor_R : std::nullopt;
  char exponent_text[32] = "?";
  if (p) std::snprintf(exponent_text, sizeof exponent_text, "%.2f", *p);
  std::string cause = "the factorisation alone grows as n^" + std::string(exponent_text) + " (" + at.back_end + ")";
  const ScaleRow* before = at.r > 0 ? &at.scale.rows[at.r - 1] : nullptr;
  if (before && before->frame_R.value && before->batch_R.value)
    cause += ", and the batch's gain over single frames went from " + times(batch_gain(*before)) + " to " +
             times(batch_gain(at.row()));
  if (global::has_cholmod())
    cause += "; below " + std::to_string(global::cholmod_from_unknowns<std::complex<double>>) +
             " unknowns the complex systems factorise on the simplicial LDLᴴ instead (sparse_factor.hpp)";
  return cause;
}

TargetVerdict target(std::string name, const std::optional<double>& measured, const std::optional<Interval>& range,
                     double limit, std::string cause) {
  const Verdict verdict = claims::verdict_of(range, {-bench::kUnbounded, limit});
  return {std::move(name), limit,   measured,
          range,           verdict, verdict == Verdict::reproduced ? std::nullopt : std::optional(std::move(cause))};
}

/// Each target alone at the size `at`, in the report's order.
std::vector<TargetVerdict> targets_at(const AtSize& at) {
  const ScaleRow& row = at.row();
  const ScaleTargets& t = at.scale.targets;
  std::vector<TargetVerdict> verdicts;
  for (const auto& [e, setup, factor] : {std::tuple{"F", &ScaleRow::setup_F, &BackEndRow::factor_F},
                                         std::tuple{"R", &ScaleRow::setup_R, &BackEndRow::factor_R}})
    verdicts.push_back(target("set-up E^" + std::string(e), (row.*setup).value, (row.*setup).runs, t.setup_ms,
                              "of its " + ms((row.*setup).cpu_ms) +
                                  " of the calling thread's CPU, the first numeric factorisation takes " +
                                  ms(at.part(factor)) + " (" + at.back_end +
                                  "); the local maps, the rotation branches, the sparsity pattern and the ordering "
                                  "take the rest"));
  verdicts.push_back(target("E^F frame", row.frame_F.value, row.frame_F.runs, t.frame_F_ms,
                            "the solve with the factor (two right-hand sides) takes " +
                                ms(at.part(&BackEndRow::solve_F)) + " of it (" + at.back_end +
                                "); the local paths and the right-hand side the rest"));
  verdicts.push_back(target("E^R batched frame", row.batch_R.value, row.batch_R.runs, t.batch_R_ms,
                            "every E^R frame is a numeric factorisation, " + ms(at.part(&BackEndRow::factor_R)) +
                                " on one thread (" + at.back_end +
                                "); a batch of 8 on the machine's cores made a "
                                "frame " +
                                times(batch_gain(row)) + " faster than one at a time"));
  verdicts.push_back(
      target("E^R batched frame's growth from the size before", at.scale.growth_R,
             at.r > 0 ? quotient_spread(row.batch_R.runs, at.scale.rows[at.r - 1].batch_R.runs) : std::nullopt,
             t.growth_R, growth_cause(at)));
  verdicts.push_back(target("peak memory (MB)", row.peak_MB.value, row.peak_MB.runs, t.peak_MB,
                            "the factors and the frames' workspaces"));
  return verdicts;
}

}  // namespace

ScaleTargets scale_targets() { return {1e6, 3000, 100, 600, 2048, 5}; }

void decide_targets(EngineScale& scale) {
  const std::vector<ScaleRow>& rows = scale.rows;
  for (std::size_t r = 0; r < rows.size(); ++r) {  // the largest size at or beyond the targets' triangles
    if (r > 0 && rows[r - 1].batch_R.value && rows[r].batch_R.value)
      scale.growth_R = *rows[r].batch_R.value / *rows[r - 1].batch_R.value;
    if (rows[r].triangles < scale.targets.triangles) continue;
    scale.target_verdicts = targets_at(at_size(scale, r));
    std::vector<Verdict> each;
    for (const TargetVerdict& v : scale.target_verdicts) each.push_back(v.verdict);
    scale.verdict = claims::all_of(each);
  }
}

}  // namespace affinterp::measurements
