#include "experiments/bench/speed_figures.hpp"

#include <utility>

namespace affinterp::bench {

namespace {

double identity(double x) { return x; }
double per_second(double ms) { return 1000.0 / ms; }

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

std::map<std::string, Figure> speed_figures(const Program& program, const BenchResults& results) {
  std::map<std::string, Figure> figures;
  const std::string name(program.name);
  const auto ratio = [&](std::string_view slow, std::string_view fast) {
    if (results[slow] && results[fast])
      figures[ratio_key(slow, fast)] = {name, "×", measured_ratio(results, slow, fast)};
  };
  if (program.name == kExp3.name) {
    for (const auto& [slow, fast] : kExp3Ratios) ratio(slow, fast);
    if (results[names::exp_ours_batched])
      figures[std::string(names::exp_ours_batched)] = {name, "ns",
                                                       measured_median(results, names::exp_ours_batched, identity)};
  } else if (program.name == kApp3.name) {
    ratio(names::app_diag, names::app_improved_sd);
  } else if (program.name == kInterp.name) {
    for (const auto& [benchmark, ms] : results.median) {
      if (!benchmark.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
      const std::string energy_mesh = benchmark.substr(6);
      figures[frame_rate_key(energy_mesh)] = {name, "frames/s", measured_median(results, benchmark, per_second)};
      if (results[setup_key(energy_mesh)])
        figures[setup_key(energy_mesh)] = {name, "ms", measured_median(results, setup_key(energy_mesh), identity)};
    }
  }
  return figures;
}

}  // namespace affinterp::bench
