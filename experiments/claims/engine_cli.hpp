#pragma once
// The CLI against the engine at a million triangles, for the report, from one run of build/bin/bench_cli_scale
// (issue 19): per energy, a frame through `affinterp interpolate` (writing its .npy included) and the engine's
// own frame on the same pair (issue 19's spiral, 2000 × 250 quads), against the target of at most 1.3 times.
#include <nlohmann/json.hpp>

#include <filesystem>

namespace affinterp::claims {

/// {"file", "machine", "triangles", "target_ratio", "rows": [{"energy", "cli_frame_ms", "engine_frame_ms" (medians
/// of the run's repetitions), "extra_frames" (the CLI's long run's frames beyond its short run's), and the ratio as
/// speed_verdict.hpp's to_json writes it against the band [0, 1.3] ("ratio", "ratio_ci95": its bootstrap interval,
/// null below kMinRepetitions; "band", "repetitions", "processes", "verdict"), and where bench_cli_scale also wrote
/// into memory "cli_memory_frame_ms", "memory_ratio", "memory_ratio_ci95"}], "verdict" (all rows': speed_verdict.hpp)};
/// a row's verdict is reproduced when the interval lies at or below the target, not-reproduced when above it, else
/// inconclusive. Null when `bench_file` does not exist.
nlohmann::json engine_cli(const std::filesystem::path& bench_file);

}  // namespace affinterp::claims
