#pragma once
// How the global engine's cost grows with the mesh, for the report, from one run of build/bin/bench_scale
// (issue 12, "Scale"): per mesh size the set-up time and the time per frame for E^F and E^R, and the peak
// memory, against the targets at 1M triangles on 2 cores — set-up ≤ 5 s, E^F ≤ 0.1 s and E^R ≤ 0.6 s per
// frame, peak memory ≤ 2 GB — and a figure of cost against size.
#include "experiments/claims/context.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace affinterp::claims {

/// {"file", "machine", "compiler", "flags", "rows": [{"triangles", "setup_F_ms", "setup_R_ms", "frame_F_ms",
/// "frame_R_ms" (wall-clock), the same with "_cpu_ms" (the process's CPU time: close to the wall-clock on an
/// idle machine, as the engine runs on one thread), "peak_MB"}] (ascending size; null: not measured), "targets":
/// {"triangles", "setup_ms", "frame_F_ms", "frame_R_ms", "peak_MB"}, "met" (null when no size reaches the targets' 1M
/// triangles, else whether the largest such size meets all four, on wall-clock times), "figures" (the drawn cost curve,
/// when `settings` draws figures)}; null when `bench_file` does not exist.
nlohmann::json engine_scale(const std::filesystem::path& bench_file, const RunSettings& settings);

}  // namespace affinterp::claims
