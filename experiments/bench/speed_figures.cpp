#include "experiments/bench/speed_figures.hpp"

#include <utility>

namespace affinterp::bench {

namespace {

double identity(double x) { return x; }
double per_second(double ms) { return 1000.0 / ms; }  // ms per frame → frames per second

/// The ratios read from bench_exp3: thesis Figs 3.1, 3.2 and the suite's own exponential against its peers.
constexpr std::pair<std::string_view, std::string_view> kExp3Ratios[] = {
    {names::eig_qr, names::eig_viete},
    {names::exp_diag, names::exp_improved_sd},
    {names::exp_diag, names::exp_sd},
    {names::exp_sd, names::exp_improved_sd},
    {names::exp_direct_diag, names::exp_ours},
    {names::exp_pade, names::exp_ours},
    {names::exp_direct_diag, names::exp_ours_batched},
};

}  // namespace

std::string ratio_key(std::string_view slow, std::string_view fast) {
  return std::string(slow) + " ÷ " + std::string(fast);
}
std::string frame_rate_key(std::string_view energy_mesh) { return "frame/" + std::string(energy_mesh); }
std::string setup_key(std::string_view energy_mesh) { return "setup/" + std::string(energy_mesh); }

FigureReads figure_reads(std::string_view key) {
  static constexpr std::string_view divide = " ÷ ";
  if (const std::size_t at = key.find(divide); at != std::string_view::npos)
    return {{std::string(key.substr(0, at)), std::string(key.substr(at + divide.size()))}, nullptr};
  return {{std::string(key)}, key.starts_with("frame/") ? per_second : identity};
}

std::map<std::string, Figure> speed_figures(const Program& program, const BenchResults& results) {
  std::map<std::string, Figure> figures;
  const std::string name(program.name);
  const auto ratio = [&](std::string_view slow, std::string_view fast) {
    if (results[slow] && results[fast])
      figures[ratio_key(slow, fast)] = {name, "×", measured_ratio(results, slow, fast)};
  };
  const auto median = [&](const std::string& key, const char* unit) {
    const FigureReads reads = figure_reads(key);
    if (results[reads.benchmarks.front()])
      figures[key] = {name, unit, measured_median(results, reads.benchmarks.front(), reads.of_median)};
  };
  if (program.name == kExp3.name) {
    for (const auto& [slow, fast] : kExp3Ratios) ratio(slow, fast);
    median(std::string(names::exp_ours_batched), "ns");
  } else if (program.name == kApp3.name) {
    ratio(names::app_diag, names::app_improved_sd);
  } else if (program.name == kInterp.name) {
    for (const auto& [benchmark, ms] : results.median) {
      if (!benchmark.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
      const std::string energy_mesh = benchmark.substr(6);
      median(frame_rate_key(energy_mesh), "frames/s");
      median(setup_key(energy_mesh), "ms");
    }
  }
  return figures;
}

}  // namespace affinterp::bench
