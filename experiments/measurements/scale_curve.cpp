#include "experiments/measurements/scale_curve.hpp"

#include "plots/engine_scale_curve.hpp"

#include <cstdio>
#include <utility>

namespace affinterp::measurements {
namespace {

/// One line: the points of `cost` over `rows`, titled with its exponent; none without points.
template <class Row>
std::optional<plots::CostSeries> series_of(const std::vector<Row>& rows, Cost Row::*cost,
                                           const std::optional<double>& exponent, std::string title, int colour,
                                           int dash, bool memory) {
  plots::CostSeries s{std::move(title), {}, colour, dash, memory};
  for (const Row& row : rows)
    if ((row.*cost).value) s.points.push_back({row.triangles, *(row.*cost).value});
  if (s.points.empty()) return std::nullopt;
  if (exponent) {
    char fitted[32];
    std::snprintf(fitted, sizeof fitted, " (n^{%.2f})", *exponent);
    s.title += fitted;
  }
  return s;
}

}  // namespace

std::vector<std::string> draw_cost_curve(const claims::RunSettings& settings, const EngineScale& scale) {
  std::vector<plots::CostSeries> series;
  const auto add = [&series](std::optional<plots::CostSeries> s) {
    if (s) series.push_back(std::move(*s));
  };
  int dash = 2;
  for (const BackEnd& b : scale.back_ends) {
    const BackEndExponents& p = b.exponents;
    add(series_of(b.rows, &BackEndRow::setup_F, p.setup_F, "set-up E^F, " + b.name, 1, dash, false));
    add(series_of(b.rows, &BackEndRow::setup_R, p.setup_R, "set-up E^R, " + b.name, 2, dash, false));
    add(series_of(b.rows, &BackEndRow::frame_F, p.frame_F, "E^F frame, " + b.name, 3, dash, false));
    add(series_of(b.rows, &BackEndRow::frame_R, p.frame_R, "E^R frame, " + b.name, 4, dash, false));
    ++dash;
  }
  add(series_of(scale.rows, &ScaleRow::batch_R, scale.exponents.batch_R, "E^R frame, batched (engine)", 4, 1, false));
  add(series_of(scale.rows, &ScaleRow::peak_MB, scale.exponents.peak_MB, "peak memory, MB (engine, right axis)", 7, 1,
                true));
  const ScaleTargets& t = scale.targets;
  return claims::RunSettings::figure_refs(plots::draw_engine_scale(settings.figure_stem("engine-scale"), series,
                                                                   {{t.setup_ms, "set-up target at 1M", false},
                                                                    {t.batch_R_ms, "E^R batched frame target", false},
                                                                    {t.frame_F_ms, "E^F frame target", false},
                                                                    {t.peak_MB, "memory target", true}}));
}

}  // namespace affinterp::measurements
