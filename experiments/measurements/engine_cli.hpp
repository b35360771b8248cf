#pragma once
// The CLI against the engine at a million triangles, from one run of build/bin/bench_cli_scale: per energy, a
// frame through `affinterp interpolate` (writing its .npy included) and the engine's own frame on the same pair
// (the strip spiral, 2000 × 250 quads), against the target of at most 1.3 times the engine.
#include "experiments/measurements/bench_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// One energy's frame through the CLI against the engine's.
struct CliRow {
  std::string energy;
  double cli_frame_ms = 0;                  ///< the median of the run's repetitions
  double engine_frame_ms = 0;               ///< the same
  std::optional<double> extra_frames;       ///< the CLI's long run's frames beyond its short run's
  bench::Measured ratio;                    ///< CLI / engine, with its bootstrap interval (null below kMinRepetitions)
  Interval band;                            ///< the ratios that meet the target, [0, 1.3]
  Verdict verdict = Verdict::inconclusive;  ///< the interval at or below the target: reproduced; above: not
  /// The same CLI runs writing into memory (/dev/shm), where bench_cli_scale measured them.
  std::optional<double> cli_memory_frame_ms;
  std::optional<double> memory_ratio;         ///< CLI into memory / engine
  std::optional<Interval> memory_ratio_ci95;  ///< its bootstrap interval
};

struct EngineCli {
  BenchRun run;
  std::optional<double> triangles;
  double target_ratio = 0;
  std::vector<CliRow> rows;
  std::optional<Verdict> verdict;  ///< all rows' (speed_verdict.hpp's all_of); null without rows
};

/// The record of `bench_file`; nullopt when it does not exist.
std::optional<EngineCli> engine_cli(const std::filesystem::path& bench_file);

/// claims.json's "engine_cli": {"file", "date", "machine", "compiler", "flags", "triangles", "target_ratio",
/// "rows": [{"energy", "cli_frame_ms", "engine_frame_ms", "extra_frames", the ratio as speed_verdict.hpp's to_json
/// writes it ("ratio", "ratio_ci95", "band", "repetitions", "processes", "verdict"), "cli_memory_frame_ms",
/// "memory_ratio", "memory_ratio_ci95"}], "verdict"}; keys of what was not measured are left out.
void to_json(nlohmann::json& json, const EngineCli& cli);
void from_json(const nlohmann::json& json, EngineCli& cli);

}  // namespace affinterp::measurements
