#include "experiments/claims/engine_scale.hpp"

#include "experiments/claims/bench_results.hpp"
#include "plots/figure.hpp"
#include "plots/gnuplot_process.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>

namespace affinterp::claims {
namespace {

constexpr double target_triangles = 1e6, setup_target_ms = 5000, frame_F_target_ms = 100, frame_R_target_ms = 600,
                 peak_target_MB = 2048;

bool at_most(const nlohmann::json& value, double target) { return value.is_number() && value.get<double>() <= target; }

/// Time (ms) against triangles, log-log, one line per measured quantity.
std::vector<std::string> draw_cost_curve(const RunSettings& settings, const nlohmann::json& rows) {
  const std::vector<std::pair<std::string, std::string>> columns = {{"setup_F_ms", "set-up, E^F"},
                                                                    {"setup_R_ms", "set-up, E^R"},
                                                                    {"frame_F_ms", "one frame, E^F"},
                                                                    {"frame_R_ms", "one frame, E^R"}};
  plots::Figure figure(settings.figure_stem("engine-scale"));
  std::string plot = "plot ";
  for (std::size_t c = 0; c < columns.size(); ++c) {
    plots::Table table;
    for (const auto& row : rows)
      if (row[columns[c].first].is_number())
        table.push_back({row["triangles"].get<double>(), row[columns[c].first].get<double>()});
    figure.data("c" + std::to_string(c), table);
    plot += std::string(c ? ", " : "") + "$c" + std::to_string(c) + " using 1:2 with linespoints title " +
            plots::gnuplot_string(columns[c].second);
  }
  figure.size(900, 560).script(
      "set logscale xy\nset xlabel 'triangles'\nset ylabel 'time (ms)'\nset key top left\n"
      "set title 'global engine: cost against mesh size (bench\\_scale)'\n"
      "set arrow from graph 0, first 5000 to graph 1, first 5000 nohead dt 2 lc rgb '#888888'\n"
      "set arrow from graph 0, first 600 to graph 1, first 600 nohead dt 3 lc rgb '#888888'\n"
      "set arrow from graph 0, first 100 to graph 1, first 100 nohead dt 4 lc rgb '#888888'\n"
      "set label 'set-up target at 1M' at graph 0.7, first 5000 offset 0,0.6 tc rgb '#666666'\n"
      "set label 'E^R frame target' at graph 0.7, first 600 offset 0,0.6 tc rgb '#666666'\n"
      "set label 'E^F frame target' at graph 0.7, first 100 offset 0,0.6 tc rgb '#666666'\n" +
      plot + "\n");
  return RunSettings::figure_refs(figure.render());
}

}  // namespace

nlohmann::json engine_scale(const std::filesystem::path& bench_file, const RunSettings& settings) {
  const std::optional<BenchResults> times = read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<BenchResults> cpu = read_bench_results(bench_file, "cpu_time");
  const std::optional<BenchResults> peaks = read_bench_results(bench_file, "peak_MB");
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
