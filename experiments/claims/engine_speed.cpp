#include "experiments/claims/engine_speed.hpp"

#include "experiments/claims/bench_results.hpp"
#include "experiments/claims/measured.hpp"

#include <optional>
#include <string>

namespace affinterp::claims {
namespace {

constexpr double setup_target_ms = 200.0;

std::optional<double> frames_per_second_target(const std::string& energy) {
  if (energy == "F") return 150.0;
  if (energy == "R") return 25.0;
  return std::nullopt;
}

nlohmann::json optional_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(); }

nlohmann::json interval(const Measured& m) {
  return m.ci95 ? nlohmann::json{m.ci95->lo, m.ci95->hi} : nlohmann::json();
}

double identity(double x) { return x; }
double per_second(double ms) { return 1000.0 / ms; }

}  // namespace

nlohmann::json engine_speed(const std::filesystem::path& bench_file) {
  const std::optional<BenchResults> times = read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<BenchResults> sizes = read_bench_results(bench_file, "triangles");
  nlohmann::json table{{"file", bench_file.filename().string()},
                       {"machine", times->machine},
                       {"compiler", times->compiler},
                       {"flags", times->flags},
                       {"rows", nlohmann::json::array()}};
  for (const auto& [name, frame_ms] : times->median) {
    if (!name.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
    const std::string rest = name.substr(6);
    const std::string energy = rest.substr(0, rest.find('/')), mesh = rest.substr(rest.find('/') + 1);
    const std::optional<double> setup_ms = (*times)["setup/" + rest], baseline_ms = (*times)["frame_refactor/" + rest];
    const std::optional<double> target = frames_per_second_target(energy);
    // Each target is met (reproduced) iff the 95% bootstrap interval of its median lies in its band.
    const Measured frames_per_s = measured_median(*times, name, per_second);
    const Interval frames_band{target.value_or(0), kUnbounded}, setup_band{0, setup_target_ms};
    Verdict verdict = Verdict::inconclusive;  // without a set-up time
    nlohmann::json setup_ci;
    if (setup_ms) {
      const Measured setup = measured_median(*times, "setup/" + rest, identity);
      setup_ci = interval(setup);
      verdict = all_of({verdict_of(setup, setup_band), verdict_of(frames_per_s, frames_band)});
    }
    table["mesh"] = mesh;
    if (const auto triangles = sizes ? (*sizes)["setup/" + rest] : std::nullopt) table["triangles"] = *triangles;
    table["rows"].push_back({
        {"energy", energy},
        {"setup_ms", optional_number(setup_ms)},
        {"setup_ms_ci95", setup_ci},
        {"setup_target_ms", setup_target_ms},
        {"frame_ms", frame_ms},
        {"frames_per_s", frames_per_s.value},
        {"frames_per_s_ci95", interval(frames_per_s)},
        {"target_frames_per_s", optional_number(target)},
        {"repetitions", frames_per_s.repetitions},
        {"baseline_ms", optional_number(baseline_ms)},
        {"speedup_vs_baseline", baseline_ms ? nlohmann::json(*baseline_ms / frame_ms) : nlohmann::json()},
        {"verdict", to_string(verdict)},
    });
  }
  return table;
}

}  // namespace affinterp::claims
