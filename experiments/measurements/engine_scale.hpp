#pragma once
// How the global engine's cost grows with the mesh, from one run of build/bin/bench_scale: per mesh size from 1k
// to 1M triangles the set-up time, the time per frame for E^F and E^R (one frame, and E^R's batched frames
// amortised) and the peak memory, each back-end's set-up, frames, factorisation and solve side by side, and the
// exponent of each cost's growth, against the targets at 1M triangles on 2 cores: set-up ≤ 3 s, E^F ≤ 0.1 s a
// frame, E^R ≤ 0.6 s a batched frame, peak memory ≤ 2 GB, and E^R's batched frame growing at most 5 times from
// the size before (261k) to 1M; and a figure of cost against size.
#include "experiments/claims/context.hpp"
#include "experiments/measurements/bench_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// One cost at one size: the median of its runs (wall-clock ms, or MB for memory), the calling thread's CPU time
/// (ms), and the least and the largest of its runs (null: the file holds no repetitions).
struct Cost {
  std::optional<double> value, cpu_ms;
  std::optional<Interval> runs;
};

/// The engine at one size, on the back-end it picks by size. A batched frame is vertices_at(times) of 8 frames on
/// the machine's cores, per frame (no CPU time); the peak is the process's resident high-water mark over the
/// size's benchmarks.
struct ScaleRow {
  double triangles = 0;
  Cost setup_F, setup_R, frame_F, frame_R, batch_F, batch_R, peak_MB;
};

/// The exponent p of each cost ≈ c · triangles^p, fitted from EngineScale::exponents_from_triangles up (null:
/// undetermined).
struct ScaleExponents {
  std::optional<double> setup_F, setup_R, frame_F, frame_R, batch_R, peak_MB;
};

/// One back-end alone on the same matrices (backend_*: E^F's real L with two right-hand sides, E^R's complex
/// H(½) with one), in ms and the calling thread's CPU ms (no runs' spread).
struct BackEndRow {
  double triangles = 0;
  Cost setup_F, setup_R, frame_F, frame_R, factor_F, factor_R, solve_F, solve_R;
};
struct BackEndExponents {
  std::optional<double> setup_F, setup_R, frame_F, frame_R, factor_F, factor_R, solve_F, solve_R;
};
struct BackEnd {
  std::string name;
  std::vector<BackEndRow> rows;  ///< ascending size
  BackEndExponents exponents;
};

/// The targets at `triangles`: set-up, E^F frame, E^R batched frame (ms), peak (MB), E^R's batched growth.
struct ScaleTargets {
  double triangles = 0, setup_ms = 0, frame_F_ms = 0, batch_R_ms = 0, peak_MB = 0, growth_R = 0;
};

/// One target alone at the largest size at or beyond the targets' triangles: the median of its runs, their
/// least and largest (for the growth, over every pairing of the two sizes' runs), the verdict on that spread
/// against "at most `limit`" by the speed tables' interval rule (reproduced: every run meets it; not-reproduced:
/// none does; else, or without a spread, inconclusive) and, when it is not met, where the time goes.
struct TargetVerdict {
  std::string target;
  double limit = 0;
  std::optional<double> measured;
  std::optional<Interval> range;
  Verdict verdict = Verdict::inconclusive;
  std::optional<std::string> cause;
};

/// From how many unknowns the engine factorises on CHOLMOD: E^F's real system and the complex ones.
struct CholmodSwitch {
  long real = 0, complex = 0;
};

struct EngineScale {
  BenchRun run;
  std::string blas;                                    ///< the BLAS the benchmarks loaded
  std::optional<CholmodSwitch> cholmod_from_unknowns;  ///< null: built without CHOLMOD
  std::vector<ScaleRow> rows;                          ///< ascending size
  ScaleExponents exponents;
  double exponents_from_triangles = 0;
  std::optional<double> growth_R;  ///< batch_R at the largest size over the size before
  std::vector<BackEnd> back_ends;
  ScaleTargets targets;
  std::optional<Verdict> verdict;  ///< all_of the target verdicts; null when no size reaches the targets' size
  std::vector<TargetVerdict> target_verdicts;
  std::vector<std::string> figures;  ///< the drawn cost curve, when the settings draw figures
};

/// The record of `bench_file`; nullopt when it does not exist.
std::optional<EngineScale> engine_scale(const std::filesystem::path& bench_file, const claims::RunSettings& settings);

/// claims.json's "engine_scale": {"file", "date", "machine", "compiler", "flags", "blas", "cholmod_from_unknowns":
/// {"real", "complex"}, "rows": [{"triangles", "setup_F_ms", "setup_F_cpu_ms", "setup_F_range", the same for
/// setup_R, frame_F and frame_R, "batch_F_ms", "batch_F_range", "batch_R_ms", "batch_R_range", "peak_MB",
/// "peak_MB_range"}], "exponents": {"setup_F_ms", ..., "batch_R_ms", "peak_MB"}, "exponents_from_triangles",
/// "growth_R", "back_ends": [{"name", "rows": [{"triangles", "<cost>_ms", "<cost>_cpu_ms"}], "exponents":
/// {"<cost>_ms"}}], "targets": {"triangles", "setup_ms", "frame_F_ms", "batch_R_ms", "peak_MB", "growth_R"},
/// "verdict", "target_verdicts": [{"target", "limit", "measured", "range", "verdict", "cause"}], "figures"}; null
/// for what was not measured.
void to_json(nlohmann::json& json, const EngineScale& scale);
void from_json(const nlohmann::json& json, EngineScale& scale);

}  // namespace affinterp::measurements
