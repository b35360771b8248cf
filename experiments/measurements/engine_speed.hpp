#pragma once
// The global engine's speed, from one run of build/bin/bench_interp (Kaji Appendix, "Efficiency"): per energy the
// set-up time, the time per frame after set-up and, where measured, the refactor-every-frame baseline of the same
// run, against the targets of the engine's specification (E^F ≥ 150 frames/s, E^R ≥ 25 frames/s, set-up ≤ 0.2 s,
// one frame at a time) and the raised ones (E^F ≥ 300, E^R ≥ 60 frames/s, one at a time or batched); and the same
// targets on every recorded run of the history.
#include "experiments/bench/history.hpp"
#include "experiments/measurements/bench_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// Where one frame's time goes: the medians of bench_interp's frame_rhs, frame_assembly, frame_factor and
/// frame_solve (each null where the energy's frame has no such part), a frame's threads, and the frame's median
/// less its parts (negative when the parts, timed apart, sum past it).
struct FrameParts {
  std::optional<double> right_hand_side_ms, assembly_ms, factor_ms;
  double solve_ms = 0;
  std::optional<double> threads;
  double rest_ms = 0;
};

/// One energy on the run's mesh. Each target is met (reproduced) iff the 95% bootstrap interval of its median
/// lies in its band (measured.hpp; null with fewer than 10 repetitions), missed iff it lies outside.
struct SpeedRow {
  std::string energy;
  std::optional<double> setup_ms;
  std::optional<Interval> setup_ms_ci95;
  double setup_target_ms = 0;
  double frame_ms = 0;
  bench::Measured frames_per_s;  ///< one frame at a time: its value, interval, repetitions, processes
  std::optional<double> target_frames_per_s;
  std::optional<double> baseline_ms;           ///< refactorising every frame from scratch; null: not measured
  std::optional<double> speedup_vs_baseline;   ///< baseline_ms / frame_ms
  Verdict verdict = Verdict::inconclusive;     ///< the set-up and frame-rate targets together
  std::optional<double> batched_frames_per_s;  ///< 8 frames a call to vertices_at(times); null: not measured
  std::optional<Interval> batched_frames_per_s_ci95;
  std::optional<double> raised_target_frames_per_s;
  std::optional<Verdict> raised_verdict, raised_verdict_batched;
  std::optional<FrameParts> frame_parts;
};

/// One energy on one recorded run (bench/history.hpp), decided alone.
struct RunSpeed {
  std::string run, date, cpu, energy, mesh;
  bool recorded = true;
  std::optional<long> cores;
  bench::Measured frames_per_s;
  std::optional<double> target_frames_per_s;
  std::optional<bench::Measured> setup_ms;
  Verdict verdict = Verdict::inconclusive;
};

/// One energy on one machine: its runs pooled (bench/pooled.hpp) and decided on the pooled intervals.
struct MachineSpeed {
  std::string machine, energy, mesh;
  std::size_t runs = 0;
  bench::Measured frames_per_s;
  std::optional<bench::Measured> setup_ms;
  Verdict verdict = Verdict::inconclusive;
};

/// Every recorded run decided alone, every machine's runs pooled, and each energy across machines
/// (speed_verdict.hpp's across_machines, the rule the speed claims follow, quoted in `rule`).
struct SpeedHistory {
  std::vector<RunSpeed> rows;
  std::vector<MachineSpeed> machines;
  std::map<std::string, Verdict> across_machines;
  std::string rule;
};

struct EngineSpeed {
  BenchRun run;
  std::string mesh;
  std::optional<double> triangles;
  std::vector<SpeedRow> rows;
  std::optional<SpeedHistory> history;
};

/// The record of `bench_file` (without history); nullopt when it does not exist.
std::optional<EngineSpeed> engine_speed(const std::filesystem::path& bench_file);

/// The same targets on every recorded run decided alone, on each machine's runs pooled, and across machines.
SpeedHistory engine_speed_history(const std::vector<bench::RecordedRun>& runs);

/// claims.json's "engine_speed": {"file", "date", "machine", "compiler", "flags", "mesh", "triangles", "rows":
/// [{"energy", "setup_ms", "setup_ms_ci95", "setup_target_ms", "frame_ms", "frames_per_s", "frames_per_s_ci95",
/// "repetitions", "processes", "target_frames_per_s", "baseline_ms", "speedup_vs_baseline", "verdict",
/// "batched_frames_per_s", "batched_frames_per_s_ci95", "raised_target_frames_per_s", "raised_verdict",
/// "raised_verdict_batched", "frame_parts": {"right_hand_side_ms", "assembly_ms", "factor_ms", "solve_ms",
/// "threads", "rest_ms"}}], "history": {"rows": [{"run", "recorded", "date", "cpu", "cores", "energy", "mesh",
/// "frames_per_s", "frames_per_s_ci95", "target_frames_per_s", "setup_ms", "setup_ms_ci95", "processes",
/// "verdict"}], "machines": [{"machine", "energy", "mesh", "runs", "frames_per_s", "frames_per_s_ci95",
/// "setup_ms", "setup_ms_ci95", "verdict"}], "across_machines": {energy: verdict}, "rule"}}; null for what was not
/// measured.
void to_json(nlohmann::json& json, const EngineSpeed& speed);
void from_json(const nlohmann::json& json, EngineSpeed& speed);

}  // namespace affinterp::measurements
