#pragma once
// The global engine's speed table for the report, from one run of build/bin/bench_interp (Kaji Appendix,
// "Efficiency"): per energy the set-up time, the time per frame after set-up and, where measured, the
// refactor-every-frame baseline of the same run, against the targets of the engine's specification —
// E^F ≥ 150 frames/s, E^R ≥ 25 frames/s, set-up ≤ 0.2 s, one frame at a time.
#include "experiments/bench/history.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace affinterp::claims {

/// {"file", "machine", "compiler", "flags", "mesh", "triangles", "rows": [{"energy", "setup_ms", "setup_ms_ci95",
/// "setup_target_ms", "frame_ms", "frames_per_s", "frames_per_s_ci95", "target_frames_per_s" (null: none),
/// "repetitions", "baseline_ms" (null: not measured), "speedup_vs_baseline", "verdict", "batched_frames_per_s" and
/// its "…_ci95" (8 frames a call to vertices_at(times) on the machine's cores; null: not measured), issue 19's
/// "raised_target_frames_per_s" (E^F 300, E^R 60) and its "raised_verdict" one frame at a time and
/// "raised_verdict_batched", and "frame_parts" (null: not measured): where one frame's time goes, the medians of
/// bench_interp's frame_rhs, frame_assembly, frame_factor and frame_solve, {"right_hand_side_ms", "assembly_ms",
/// "factor_ms" (each null where the energy's frame has no such part), "solve_ms", "threads" (a frame's), "rest_ms"
/// (the frame's median less its parts)}}]}; null when
/// `bench_file` does not exist. The medians' 95% bootstrap intervals (measured.hpp; null with fewer than 10
/// repetitions) decide each row as the speed claims are decided: "reproduced" (targets met) when every
/// interval lies within its target, "not-reproduced" when one lies outside, else "inconclusive".
nlohmann::json engine_speed(const std::filesystem::path& bench_file);

/// The same targets on every recorded run (bench/history.hpp), each run decided alone and the runs together by
/// across_runs (speed_verdict.hpp): {"rows": [{"run", "recorded", "date", "cpu", "cores", "energy", "mesh",
/// "frames_per_s", "frames_per_s_ci95", "target_frames_per_s", "setup_ms", "setup_ms_ci95", "processes",
/// "verdict"}], "across_runs": {energy: verdict}, "rule"}.
nlohmann::json engine_speed_by_run(const std::vector<bench::RecordedRun>& runs);

}  // namespace affinterp::claims
