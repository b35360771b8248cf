#include "experiments/claims/engine_scale.hpp"

#include "experiments/bench/bench_results.hpp"
#include "plots/engine_scale_curve.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace affinterp::claims {
namespace {

constexpr double target_triangles = 1e6, setup_target_ms = 5000, frame_F_target_ms = 100, frame_R_target_ms = 600,
                 peak_target_MB = 2048;

bool at_most(const nlohmann::json& value, double target) { return value.is_number() && value.get<double>() <= target; }

/// Time (ms) against triangles, log-log, one line per measured quantity (plots/engine_scale_curve.hpp).
std::vector<std::string> draw_cost_curve(const RunSettings& settings, const nlohmann::json& rows) {
  std::vector<plots::CostSeries> series;
  for (const auto& [key, title] :
       {std::pair{"setup_F_ms", "set-up, E^F"}, std::pair{"setup_R_ms", "set-up, E^R"},
        std::pair{"frame_F_ms", "one frame, E^F"}, std::pair{"frame_R_ms", "one frame, E^R"}}) {
    plots::CostSeries& s = series.emplace_back(plots::CostSeries{title, {}});
    for (const auto& row : rows)
      if (row[key].is_number()) s.points.push_back({row["triangles"].get<double>(), row[key].get<double>()});
  }
  return RunSettings::figure_refs(plots::draw_engine_scale(settings.figure_stem("engine-scale"), series,
                                                           {{setup_target_ms, "set-up target at 1M"},
                                                            {frame_R_target_ms, "E^R frame target"},
                                                            {frame_F_target_ms, "E^F frame target"}}));
}

}  // namespace

nlohmann::json engine_scale(const std::filesystem::path& bench_file, const RunSettings& settings) {
  const std::optional<bench::BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<bench::BenchResults> cpu = bench::read_bench_results(bench_file, "cpu_time");
  const std::optional<bench::BenchResults> peaks = bench::read_bench_results(bench_file, "peak_MB");
  // scale_<setup|frame>/<energy>/<triangles>
  std::map<double, nlohmann::json> by_size;
  for (const auto& [name, ms] : times->median) {
    const std::size_t first = name.find('/'), second = name.find('/', first + 1);
    if (!name.starts_with("scale_") || second == std::string::npos) continue;
    const std::string kind = name.substr(6, first - 6), energy = name.substr(first + 1, second - first - 1);
    const double triangles = std::stod(name.substr(second + 1));
    nlohmann::json& row = by_size[triangles];
    row["triangles"] = triangles;
    row[kind + "_" + energy + "_ms"] = ms;
    if (const auto cpu_ms = cpu ? (*cpu)[name] : std::nullopt) row[kind + "_" + energy + "_cpu_ms"] = *cpu_ms;
    if (const auto peak = peaks ? (*peaks)[name] : std::nullopt)
      row["peak_MB"] = std::max(row.value("peak_MB", 0.0), *peak);
  }
  nlohmann::json rows = nlohmann::json::array();
  for (auto& [triangles, row] : by_size) {
    for (const char* key : {"setup_F_ms", "setup_R_ms", "frame_F_ms", "frame_R_ms", "setup_F_cpu_ms", "setup_R_cpu_ms",
                            "frame_F_cpu_ms", "frame_R_cpu_ms", "peak_MB"})
      if (!row.contains(key)) row[key] = nullptr;
    rows.push_back(row);
  }
  nlohmann::json met = nullptr;
  for (const auto& row : rows)  // the largest size at or beyond the targets' 1M triangles
    if (row["triangles"].get<double>() >= target_triangles)
      met = at_most(row["setup_F_ms"], setup_target_ms) && at_most(row["setup_R_ms"], setup_target_ms) &&
            at_most(row["frame_F_ms"], frame_F_target_ms) && at_most(row["frame_R_ms"], frame_R_target_ms) &&
            at_most(row["peak_MB"], peak_target_MB);
  return {{"file", bench_file.filename().string()},
          {"machine", times->machine},
          {"compiler", times->compiler},
          {"flags", times->flags},
          {"rows", rows},
          {"targets",
           {{"triangles", target_triangles},
            {"setup_ms", setup_target_ms},
            {"frame_F_ms", frame_F_target_ms},
            {"frame_R_ms", frame_R_target_ms},
            {"peak_MB", peak_target_MB}}},
          {"met", met},
          {"figures", settings.draws_figures() && !rows.empty() ? nlohmann::json(draw_cost_curve(settings, rows))
                                                                : nlohmann::json::array()}};
}

}  // namespace affinterp::claims
