// How the global engine's cost grows with the mesh: set-up (local maps, rotation
// branches, sparsity pattern, symbolic analysis, first factorisation), time per frame for E^F and E^R, and
// peak memory, on the project's man bent by a circular curl through one radian along its width
// (bench_interp's stand-in for the octopus): meshed by CGAL with edges up to 0.0137 (65,326 triangles) and
// 2, 4, 8 times that (16k, 4k, 1k triangles), and the 65k pair subdivided 1-to-4 once and twice (261,304 and
// 1,045,216 triangles: shapes/subdivide.hpp). The options are those of `affinterp interpolate`: area
// weights, the straight barycentre locus, and for E^R the default gauge edge. Peak memory: getrusage's
// ru_maxrss, its high-water mark reset (Linux /proc/self/clear_refs) before each benchmark builds its
// Interpolation, so each counter is that benchmark's own peak of the whole process (the cached meshes
// included). Targets at 1M triangles on 2 cores: experiments/measurements/engine_scale.hpp.
// scale_* with the back-end the engine picks by size (theory/global/sparse_factor.hpp, what the report's
// engine_scale reads) and batch_frames/E/size: vertices_at(times) of 8 frames at once, in parallel on the
// machine's cores (frames_per_s, the amortised cost); backend_* on each back-end by name (…/simplicial,
// …/cholmod when built in), side by side: set-up, one frame, and one numeric factorisation and one solve of
// the frame's system (what the back-end switch is set from).
// Run with --benchmark_filter to leave out the largest size (it takes minutes).
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/apps/bench/engine_bench.hpp"
#include "experiments/inputs/shapes/curl.hpp"
#include "experiments/inputs/shapes/man.hpp"
#include "experiments/inputs/shapes/subdivide.hpp"
#include "theory/global/frame_assembly.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/sparse_factor.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace affinterp {
namespace {

using global::Energy;

/// The ladder of sizes: level 0 is the man meshed with edges ≤ 0.0137 (65,326 triangles), a negative level
/// the man meshed with edges 2^−level times as long (about 4^level times the triangles: ~1k, 4k, 16k), a
/// positive one level 0 subdivided `level` times (261,304 and 1,045,216 triangles).
constexpr int coarsest_level = -3, finest_level = 2;

/// The man at `level`, bent by a circular curl through one radian along its width; built once per level.
const shapes::MeshPairShapes& workload(int level) {
  static std::map<int, shapes::MeshPairShapes> pairs;
  if (const auto found = pairs.find(level); found != pairs.end()) return found->second;
  if (level > 0) return pairs[level] = shapes::subdivided(workload(level - 1));
  shapes::MeshPairShapes pair{shapes::man(0.0137 * std::ldexp(1.0, -level)), {}};
  const Eigen::Vector2d low = pair.source.vertices.rowwise().minCoeff(),
                        high = pair.source.vertices.rowwise().maxCoeff();
  const Eigen::Vector2d centre_left(low.x(), (low.y() + high.y()) / 2);
  pair.target = pair.source;
  pair.target.vertices =
      shapes::Curl{high.x() - low.x(), 1.0, 1}.apply(Eigen::Matrix2Xd(pair.source.vertices.colwise() - centre_left), 1);
  return pairs[level] = std::move(pair);
}

/// Starts a new high-water mark of the resident set (Linux ≥ 4.0); false where that is not possible.
bool reset_peak_memory() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  return static_cast<bool>(clear_refs << "5" << std::flush);
}

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void report(benchmark::State& state, const shapes::MeshPairShapes& pair, bool peak_is_own) {
  state.counters["triangles"] = static_cast<double>(pair.source.triangle_count());
  state.counters["peak_MB"] = peak_memory_mb();
  // a label, not a counter (see bench_interp.cpp): whether peak_MB is this benchmark's own
  state.SetLabel(peak_is_own ? "peak of this benchmark" : "peak of the process so far");
}

void set_up(benchmark::State& state, Energy energy, int level, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(level);
  const global::InterpolationOptions options = bench::cli_options(energy, pair.source, pair.target, back_end);
  const bool own = reset_peak_memory();
  for (auto _ : state) {
    global::Interpolation interpolation(pair.source, pair.target, options);
    benchmark::DoNotOptimize(&interpolation);
  }
  report(state, pair, own);
}

void frame(benchmark::State& state, Energy energy, int level, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(level);
  const global::InterpolationOptions options = bench::cli_options(energy, pair.source, pair.target, back_end);
  const bool own = reset_peak_memory();
  const global::Interpolation interpolation(pair.source, pair.target, options);
  int k = 0;
  for (auto _ : state) {
    const double t = (k++ % 60 + 0.5) / 60;
    benchmark::DoNotOptimize(interpolation.vertices_at(t).data());
  }
  report(state, pair, own);
}

/// 8 frames per iteration through vertices_at(times); time per frame = iteration time / 8.
void frames_batched(benchmark::State& state, Energy energy, int level, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(level);
  const global::InterpolationOptions options = bench::cli_options(energy, pair.source, pair.target, back_end);
  const bool own = reset_peak_memory();
  bench::time_batches(state, global::Interpolation(pair.source, pair.target, options), "frames_per_s");
  report(state, pair, own);
}

/// The sparse system of a frame as the engine builds it (FrameAssembly): E^F's real L (the real part of
/// H, factored once), E^R's complex Hermitian H(½); both grounded at vertex 0 for the barycentre.
template <class Scalar>
Eigen::SparseMatrix<Scalar> frame_matrix(int level) {
  const shapes::MeshPairShapes& pair = workload(level);
  const Energy energy = std::is_same_v<Scalar, double> ? Energy::F : Energy::R;
  const global::InterpolationOptions options = bench::cli_options(energy, pair.source, pair.target);
  const bench::AssembledPair assembled(pair.source, pair.target, options);
  const global::FrameAssembly& assembly = assembled.assembly();
  global::FrameAssembly::SparseMatrix H = assembly.pattern();
  assembly.matrix_at(0.5, H);
  if constexpr (std::is_same_v<Scalar, double>) {
    Eigen::SparseMatrix<double> L = H.real();
    L.makeCompressed();
    return L;
  } else {
    return H;
  }
}

/// One numeric factorisation on the named back-end (the symbolic analysis outside the timing).
template <class Scalar>
void backend_factor(benchmark::State& state, int level, global::SparseBackEnd back_end) {
  const Eigen::SparseMatrix<Scalar> K = frame_matrix<Scalar>(level);
  const auto factor = global::make_sparse_factor<Scalar>(back_end);
  for (auto _ : state) {
    state.PauseTiming();
    factor->analyse(K);  // afresh: CHOLMOD turns a real factor into columns of its own (cholmod_factor.hpp)
    state.ResumeTiming();
    benchmark::DoNotOptimize(factor->factorise(K, 1));
  }
  state.counters["unknowns"] = static_cast<double>(K.rows());
  state.counters["factor_MB"] = factor->factor_bytes() / 1e6;
  state.counters["triangles"] = static_cast<double>(workload(level).source.triangle_count());
}

/// One solve of a frame's right-hand sides: E^F's two real columns (x and y), E^R's one complex column.
template <class Scalar>
void backend_solve(benchmark::State& state, int level, global::SparseBackEnd back_end) {
  const Eigen::SparseMatrix<Scalar> K = frame_matrix<Scalar>(level);
  const auto factor = global::make_sparse_factor<Scalar>(back_end);
  factor->analyse(K);
  if (!factor->factorise(K, 1)) state.SkipWithError("not positive definite");
  using Block = typename global::SparseFactor<Scalar>::Block;
  const Block B = Block::Ones(K.rows(), std::is_same_v<Scalar, double> ? 2 : 1);
  for (auto _ : state) {
    Block X = B;
    factor->solve_in_place(X, 1);
    benchmark::DoNotOptimize(X.data());
  }
  state.counters["unknowns"] = static_cast<double>(K.rows());
  state.counters["triangles"] = static_cast<double>(workload(level).source.triangle_count());
}

/// The engine's rows, which decide the 1M-triangle targets: five repetitions of at least half a second each (one
/// iteration at 1M), each written to the JSON file, so that a verdict rests on the spread of the runs
/// (experiments/measurements/engine_scale.hpp) and not on a median the machine's noise moves across a target.
void repeated(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->MinTime(0.5)->Repetitions(5)->DisplayAggregatesOnly(true);
}
/// Each back-end's rows, which decide no target: three repetitions, their aggregates only.
void compared(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->MinTime(0.5)->Repetitions(3)->ReportAggregatesOnly(true);
}

void register_all() {
  std::vector<global::SparseBackEnd> back_ends = {global::SparseBackEnd::simplicial};
  if (global::has_cholmod()) back_ends.push_back(global::SparseBackEnd::cholmod);
  for (int level = coarsest_level; level <= finest_level; ++level) {
    const std::string size = std::to_string(workload(level).source.triangle_count());
    for (const Energy energy : {Energy::F, Energy::R}) {
      const std::string name = global::to_string(energy) + "/" + size;
      benchmark::RegisterBenchmark(("scale_setup/" + name).c_str(), set_up, energy, level, std::nullopt)
          ->Apply(repeated);
      benchmark::RegisterBenchmark(("scale_frame/" + name).c_str(), frame, energy, level, std::nullopt)
          ->Apply(repeated);
      benchmark::RegisterBenchmark(("batch_frames/" + name).c_str(), frames_batched, energy, level, std::nullopt)
          ->Apply(repeated);
      for (const global::SparseBackEnd back_end : back_ends) {
        const std::string suffix = back_end == global::SparseBackEnd::cholmod ? "/cholmod" : "/simplicial";
        benchmark::RegisterBenchmark(("backend_setup/" + name + suffix).c_str(), set_up, energy, level, back_end)
            ->Apply(compared);
        benchmark::RegisterBenchmark(("backend_frame/" + name + suffix).c_str(), frame, energy, level, back_end)
            ->Apply(compared);
        const bool real = energy == Energy::F;
        benchmark::RegisterBenchmark(("backend_factor/" + name + suffix).c_str(),
                                     real ? backend_factor<double> : backend_factor<std::complex<double>>, level,
                                     back_end)
            ->Apply(compared);
        benchmark::RegisterBenchmark(("backend_solve/" + name + suffix).c_str(),
                                     real ? backend_solve<double> : backend_solve<std::complex<double>>, level,
                                     back_end)
            ->Apply(compared);
      }
    }
  }
}

}  // namespace
}  // namespace affinterp

int main(int argc, char** argv) {
  affinterp::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
