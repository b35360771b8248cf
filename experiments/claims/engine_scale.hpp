#pragma once
// How the global engine's cost grows with the mesh, for the report, from one run of build/bin/bench_scale
// (issue 19): per mesh size from 1k to 1M triangles the set-up time, the time per frame for E^F and E^R (one
// frame, and E^R's batched frames amortised) and the peak memory, each back-end's set-up, frames, factorisation
// and solve side by side, and the exponent of each cost's growth, against the targets at 1M triangles on 2
// cores: set-up ≤ 3 s, E^F ≤ 0.1 s a frame, E^R ≤ 0.6 s a batched frame, peak memory ≤ 2 GB, and E^R's batched
// frame growing at most 5 times from the size before (261k) to 1M; and a figure of cost against size.
#include "experiments/claims/context.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace affinterp::claims {

/// {"file", "machine", "compiler", "flags", "blas" (the BLAS the benchmarks loaded), "rows": [{"triangles",
/// "setup_F_ms", "setup_R_ms", "frame_F_ms", "frame_R_ms" (wall-clock, the median of runs), the same with
/// "_cpu_ms" (the calling thread's CPU time), "batch_F_ms", "batch_R_ms" (vertices_at(times) of 8 frames,
/// wall-clock per frame), "peak_MB", and with "_range" in place of "_ms" (for the peak: after "peak_MB") the
/// least and the largest of the runs (null: the file holds no repetitions)}] (the back-end the engine picks by
/// size; ascending size; null: not measured), "exponents" {key: p of key ≈ c · triangles^p, fitted from
/// "exponents_from_triangles" up}, "growth_R" (batch_R_ms at the largest size over the size before), "back_ends":
/// [{"name", "rows": [{"triangles", "setup_*", "frame_*", "factor_*", "solve_*" for F and R, in ms and cpu ms}],
/// "exponents"}], "targets": {"triangles", "setup_ms", "frame_F_ms", "batch_R_ms", "peak_MB", "growth_R"},
/// "verdict" (null when no size reaches the targets' 1M triangles; else, at the largest such size, all_of the
/// targets' verdicts, speed_verdict.hpp), "target_verdicts": [{"target", "limit", "measured" (the median), "range"
/// (the runs' least and largest; for the growth, over every pairing of the two sizes' runs), "verdict" (the speed
/// tables' interval rule on the range against "at most limit": "reproduced", met, when every run meets it,
/// "not-reproduced" when none does, else or without a range "inconclusive"), "cause" (when not met: where the time
/// goes, from the run's own back-end rows)}] at that size,
/// "figures" (the drawn cost curve, when `settings` draws figures)}; null when `bench_file` does not exist.
nlohmann::json engine_scale(const std::filesystem::path& bench_file, const RunSettings& settings);

}  // namespace affinterp::claims
