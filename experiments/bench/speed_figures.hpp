#pragma once
// The figures speed verdicts read (thesis §3.4's speed claims, the suite's exp3 targets, the global engine's
// frame rates), by benchmark program: each a ratio of medians or one median with its 95% bootstrap interval
// (measured.hpp). One place names them, for the history of runs (history.hpp) and for the claims.
#include "experiments/bench/bench_results.hpp"
#include "experiments/bench/measured.hpp"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::bench {

/// A benchmark program (experiments/apps/bench), its output file's stem and the counter verdicts read from it.
struct Program {
  std::string_view name;
  std::string_view counter;
};
inline constexpr Program kExp3{"bench_exp3", "ns_per_matrix"};  ///< thesis Figs 3.1, 3.2; the suite's exp3
inline constexpr Program kApp3{"bench_app3", "ns_per_frame"};   ///< thesis Fig 3.3
inline constexpr Program kInterp{"bench_interp", "real_time"};  ///< the global engine, ms per frame and set-up
/// The programs whose figures a run records, in run order.
inline constexpr Program kSpeedPrograms[] = {kExp3, kApp3, kInterp};

/// The benchmarks standing for the algorithms the verdicts compare (names from theory/sym3/algorithms.hpp).
namespace names {
inline constexpr std::string_view eig_qr = "eig3/eigen-qr";                     ///< Eigen's QR-based eigenvalues
inline constexpr std::string_view eig_viete = "eig3/viete";                     ///< thesis §3.2
inline constexpr std::string_view exp_diag = "exp3/eigen-qr-diag";              ///< thesis Algorithm 1 (Diag)
inline constexpr std::string_view exp_sd = "exp3/thesis-sd-corrected";          ///< Algorithm 2, Eigen's eigenvalues
inline constexpr std::string_view exp_improved_sd = "exp3/thesis-improved-sd";  ///< SD with Viète's eigenvalues
inline constexpr std::string_view exp_ours = "exp3/affinterp";
inline constexpr std::string_view exp_ours_batched = "exp3/affinterp-batched";
/// Its four exponentials alone (xsimd's exp), the part of its time a faster exp would take off.
inline constexpr std::string_view exp_ours_batched_exponentials = "exp3-parts/affinterp-batched-exponentials";
inline constexpr std::string_view exp_direct_diag = "exp3/eigen-direct-diag";
inline constexpr std::string_view exp_pade = "exp3/eigen-pade";
inline constexpr std::string_view app_diag = "app/eigen-qr-diag";
inline constexpr std::string_view app_improved_sd = "app/thesis-improved-sd";
}  // namespace names

/// A figure's key: "slow ÷ fast" for a ratio of medians.
std::string ratio_key(std::string_view slow, std::string_view fast);
/// The engine's figures: "frame/<energy>/<mesh>" in frames per second, "setup/<energy>/<mesh>" in ms.
std::string frame_rate_key(std::string_view energy_mesh);
std::string setup_key(std::string_view energy_mesh);

/// How a figure is computed from its benchmarks' repetitions: median(benchmarks[0]) / median(benchmarks[1]) for a
/// ratio key ("slow ÷ fast"), else of_median(median(benchmarks[0])) for a monotone of_median.
struct FigureReads {
  std::vector<std::string> benchmarks;
  double (*of_median)(double) = nullptr;  ///< null for a ratio
};
FigureReads figure_reads(std::string_view key);

/// One figure of a run, and its unit ("×", "ns", "frames/s", "ms").
struct Figure {
  std::string program;
  std::string unit;
  Measured measured;
};

/// The figures of `program` that `results` (its output) holds, by key: for bench_exp3 the eigenvalue and
/// exponential speed-ups and the suite's targets, for bench_app3 the application speed-up, for bench_interp each
/// energy's frame rate and set-up time; a figure whose benchmarks did not run is left out.
std::map<std::string, Figure> speed_figures(const Program& program, const BenchResults& results);

}  // namespace affinterp::bench
