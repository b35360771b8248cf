#include "experiments/claims/engine_speed.hpp"

#include "experiments/bench/machine_label.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <map>
#include <optional>
#include <string>

namespace affinterp::claims {
namespace {

constexpr double specified_setup_ms = 200.0;  // the engine specification's set-up target

std::optional<double> frames_per_second_target(const std::string& energy) {
  if (energy == "F") return 150.0;
  if (energy == "R") return 25.0;
  return std::nullopt;
}

nlohmann::json optional_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(); }

/// Issue 19's raised targets on the octopus: E^F ≥ 300, E^R ≥ 60 frames/s, one frame at a time or batched.
std::optional<double> raised_frames_per_second_target(const std::string& energy) {
  if (energy == "F") return 300.0;
  if (energy == "R") return 60.0;
  return std::nullopt;
}

/// Where a frame's time goes, from the run's frame_rhs, frame_assembly, frame_factor and frame_solve rows
/// (bench_interp: the parts of a frame as vertices_at(t) runs them), when it has them.
nlohmann::json frame_parts(const BenchResults& times, const std::optional<BenchResults>& threads,
                           const std::string& rest, double frame_ms) {
  const std::optional<double> solve = times["frame_solve/" + rest];
  if (!solve) return nullptr;
  nlohmann::json parts{{"solve_ms", *solve}};
  double rest_ms = frame_ms - *solve;
  for (const auto& [key, benchmark] : {std::pair{"right_hand_side_ms", "frame_rhs/"},
                                       {"assembly_ms", "frame_assembly/"},
                                       {"factor_ms", "frame_factor/"}}) {
    const std::optional<double> ms = times[benchmark + rest];
    parts[key] = optional_number(ms);
    if (ms) rest_ms -= *ms;
  }
  parts["threads"] = optional_number(threads ? (*threads)["frame_solve/" + rest] : std::nullopt);
  parts["rest_ms"] = rest_ms;
  return parts;
}

double identity(double x) { return x; }
double per_second(double ms) { return 1000.0 / ms; }
/// bench_interp's batch_frames: 8 frames per iteration (engine_bench.hpp).
double batch_per_second(double ms) { return 8000.0 / ms; }

/// One energy's targets: met (reproduced) iff the set-up's and the frame rate's intervals lie in their bands;
/// inconclusive without a set-up time.
Verdict targets_verdict(const std::optional<Measured>& setup, const Measured& frames_per_s, const std::string& energy) {
  if (!setup) return Verdict::inconclusive;
  return all_of({verdict_of(*setup, {0, specified_setup_ms}),
                 verdict_of(frames_per_s, {frames_per_second_target(energy).value_or(0), kUnbounded})});
}

}  // namespace

nlohmann::json engine_speed(const std::filesystem::path& bench_file) {
  const std::optional<BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<BenchResults> sizes = bench::read_bench_results(bench_file, "triangles");
  const std::optional<BenchResults> threads = bench::read_bench_results(bench_file, "threads");
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
    std::optional<Measured> setup;
    if (setup_ms) setup = measured_median(*times, "setup/" + rest, identity);
    const Verdict verdict = targets_verdict(setup, frames_per_s, energy);
    const nlohmann::json setup_ci = setup ? ci95_json(*setup) : nlohmann::json();
    std::optional<Measured> batched;
    if ((*times)["batch_frames/" + rest]) batched = measured_median(*times, "batch_frames/" + rest, batch_per_second);
    const std::optional<double> raised = raised_frames_per_second_target(energy);
    const auto raised_verdict = [&](const std::optional<Measured>& rate) {
      return raised && rate ? nlohmann::json(to_string(verdict_of(*rate, {*raised, kUnbounded}))) : nlohmann::json();
    };
    table["mesh"] = mesh;
    if (const auto triangles = sizes ? (*sizes)["setup/" + rest] : std::nullopt) table["triangles"] = *triangles;
    table["rows"].push_back({
        {"energy", energy},
        {"setup_ms", optional_number(setup_ms)},
        {"setup_ms_ci95", setup_ci},
        {"setup_target_ms", specified_setup_ms},
        {"frame_ms", frame_ms},
        {"frames_per_s", frames_per_s.value},
        {"frames_per_s_ci95", ci95_json(frames_per_s)},
        {"target_frames_per_s", optional_number(target)},
        {"repetitions", frames_per_s.repetitions},
        {"processes", frames_per_s.processes},
        {"baseline_ms", optional_number(baseline_ms)},
        {"speedup_vs_baseline", baseline_ms ? nlohmann::json(*baseline_ms / frame_ms) : nlohmann::json()},
        {"verdict", to_string(verdict)},
        {"batched_frames_per_s", batched ? nlohmann::json(batched->value) : nlohmann::json()},
        {"batched_frames_per_s_ci95", batched ? ci95_json(*batched) : nlohmann::json()},
        {"raised_target_frames_per_s", optional_number(raised)},
        {"raised_verdict", raised_verdict(frames_per_s)},
        {"raised_verdict_batched", raised_verdict(batched)},
        {"frame_parts", frame_parts(*times, threads, rest, frame_ms)},
    });
  }
  return table;
}

nlohmann::json engine_speed_by_run(const std::vector<bench::RecordedRun>& runs) {
  nlohmann::json rows = nlohmann::json::array();
  std::map<std::string, std::vector<Verdict>> by_energy;
  for (const bench::RecordedRun& run : runs)
    for (const auto& [key, figure] : run.figures) {
      if (!key.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
      const std::string rest = key.substr(6), energy = rest.substr(0, rest.find('/'));
      const auto setup_figure = run.figures.find(bench::setup_key(rest));
      std::optional<Measured> setup;
      if (setup_figure != run.figures.end()) setup = setup_figure->second.measured;
      const Verdict verdict = targets_verdict(setup, figure.measured, energy);
      by_energy[energy].push_back(verdict);
      rows.push_back({{"run", run.id},
                      {"recorded", run.recorded},
                      {"date", run.date},
                      {"cpu", bench::machine_label(run.machine)},
                      {"cores", run.machine.value("cores", nlohmann::json())},
                      {"energy", energy},
                      {"mesh", rest.substr(rest.find('/') + 1)},
                      {"frames_per_s", figure.measured.value},
                      {"frames_per_s_ci95", ci95_json(figure.measured)},
                      {"target_frames_per_s", optional_number(frames_per_second_target(energy))},
                      {"setup_ms", setup ? nlohmann::json(setup->value) : nlohmann::json()},
                      {"setup_ms_ci95", setup ? ci95_json(*setup) : nlohmann::json()},
                      {"processes", figure.measured.processes},
                      {"verdict", to_string(verdict)}});
    }
  nlohmann::json across = nlohmann::json::object();
  for (const auto& [energy, verdicts] : by_energy) across[energy] = to_string(across_runs(verdicts));
  return {{"rows", rows}, {"across_runs", across}, {"rule", kAcrossRunsRule}};
}

}  // namespace affinterp::claims
