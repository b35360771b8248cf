#pragma once
// The 3D engine at a million triangles, from one run of build/bin/bench_3d_scale (reproduce.sh --scale: CGAL's
// elephant subdivided four times towards its twist, E^F, exp-log): the set-up, a frame on two threads and the peak
// memory, each against its target (set-up ≤ 5 s, a frame ≤ 0.25 s, peak ≤ 3 GB on 2 cores), decided on the spread
// of the repetitions as the 2D engine's scale targets are (scale_targets.hpp): met when every repetition meets it,
// missed when none does, undecided otherwise.
#include "experiments/measurements/bench_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace affinterp::measurements {

/// One cost against its limit: the median and the least and largest repetition, and the verdict.
struct Engine3Target {
  double median = 0, limit = 0;
  Interval range;
  Verdict verdict = Verdict::inconclusive;
};

struct Engine3Scale {
  BenchRun run;
  double triangles = 0;
  Engine3Target setup_s, frame_ms, peak_MB;
};

/// The limits above: set-up 5 s, frame 250 ms, peak 3072 MB.
Engine3Scale engine3_scale_targets();

/// The record of `bench_file`; nullopt when it does not exist or its benchmarks did not run (no mesh).
std::optional<Engine3Scale> engine3_scale(const std::filesystem::path& bench_file);

/// claims.json's "engine3_scale": {"file", "date", "machine", "compiler", "flags", "triangles", "setup_s",
/// "frame_ms", "peak_MB": {"median", "limit", "range", "verdict"}}.
void to_json(nlohmann::json& json, const Engine3Scale& scale);
void from_json(const nlohmann::json& json, Engine3Scale& scale);

}  // namespace affinterp::measurements
