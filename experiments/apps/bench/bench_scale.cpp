// How the global engine's cost grows with the mesh (issue 12, "Scale"): set-up (local maps, rotation
// branches, sparsity pattern, symbolic analysis, first factorisation), time per frame for E^F and E^R, and
// peak memory, on the project's man (meshed by CGAL to 65,326 triangles) bent by a circular curl through one
// radian along its width (bench_interp's stand-in for the octopus), and on that pair subdivided 1-to-4 once
// and twice (261,304 and 1,045,216 triangles: shapes/subdivide.hpp). The
// options are those of `affinterp interpolate`: area weights, the straight barycentre locus, and for E^R the
// default gauge edge. Peak memory: getrusage's ru_maxrss, its high-water mark reset (Linux
// /proc/self/clear_refs) before each benchmark builds its Interpolation, so each counter is that
// benchmark's own peak of the whole process (the cached meshes included). Targets at 1M triangles on 2 cores:
// set-up ≤ 5 s, E^F ≤ 0.1 s and E^R ≤ 0.6 s per frame, peak ≤ 2 GB (experiments/claims/engine_scale.hpp).
// scale_* with the back-end the engine picks by size (theory/global/sparse_factor.hpp, what the report's
// engine_scale reads); backend_* the same on each back-end by name (…/simplicial, …/cholmod when built in),
// side by side; and batch_frames/E/size: vertices_at(times) of 8 frames at once, in parallel on the
// machine's cores (frames_per_s, the amortised cost).
// Run with --benchmark_filter to leave out the largest size (it takes minutes).
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/inputs/shapes/curl.hpp"
#include "experiments/inputs/shapes/man.hpp"
#include "experiments/inputs/shapes/subdivide.hpp"
#include "theory/global/gauge.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/sparse_factor.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace affinterp {
namespace {

using global::Energy;

/// The curled man, subdivided `levels` times; built once per level.
const shapes::MeshPairShapes& workload(int levels) {
  static std::vector<shapes::MeshPairShapes> pairs = [] {
    shapes::MeshPairShapes pair{shapes::man(0.0137), {}};
    const Eigen::Vector2d low = pair.source.vertices.rowwise().minCoeff(),
                          high = pair.source.vertices.rowwise().maxCoeff();
    const Eigen::Vector2d centre_left(low.x(), (low.y() + high.y()) / 2);
    pair.target = pair.source;
    pair.target.vertices = shapes::Curl{high.x() - low.x(), 1.0, 1}.apply(
        Eigen::Matrix2Xd(pair.source.vertices.colwise() - centre_left), 1);
    return std::vector{pair};
  }();
  while (static_cast<int>(pairs.size()) <= levels) pairs.push_back(shapes::subdivided(pairs.back()));
  return pairs[static_cast<std::size_t>(levels)];
}

global::InterpolationOptions options_for(Energy energy, const shapes::MeshPairShapes& pair,
                                         std::optional<global::SparseBackEnd> back_end) {
  global::InterpolationOptions options;
  options.energy = energy;
  options.back_end = back_end;
  options.area_weighted = true;
  options.constraints.barycentre = global::BarycentreLocus{};
  if (const auto edge = global::default_edge_direction(pair.source, pair.target, options))
    options.constraints.edges.push_back(*edge);
  return options;
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

void set_up(benchmark::State& state, Energy energy, int levels, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(levels);
  const global::InterpolationOptions options = options_for(energy, pair, back_end);
  const bool own = reset_peak_memory();
  for (auto _ : state) {
    global::Interpolation interpolation(pair.source, pair.target, options);
    benchmark::DoNotOptimize(&interpolation);
  }
  report(state, pair, own);
}

void frame(benchmark::State& state, Energy energy, int levels, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(levels);
  const global::InterpolationOptions options = options_for(energy, pair, back_end);
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
void frames_batched(benchmark::State& state, Energy energy, int levels, std::optional<global::SparseBackEnd> back_end) {
  const shapes::MeshPairShapes& pair = workload(levels);
  const global::InterpolationOptions options = options_for(energy, pair, back_end);
  const bool own = reset_peak_memory();
  const global::Interpolation interpolation(pair.source, pair.target, options);
  constexpr int batch = 8;
  int k = 0;
  for (auto _ : state) {
    std::vector<double> times;
    for (int j = 0; j < batch; ++j) times.push_back((k++ % 60 + 0.5) / 60);
    benchmark::DoNotOptimize(interpolation.vertices_at(times).data());
  }
  state.counters["frames_per_s"] = benchmark::Counter(batch, benchmark::Counter::kIsIterationInvariantRate);
  report(state, pair, own);
}

void register_all() {
  std::vector<std::optional<global::SparseBackEnd>> back_ends = {std::nullopt, global::SparseBackEnd::simplicial};
  if (global::has_cholmod()) back_ends.push_back(global::SparseBackEnd::cholmod);
  for (int levels = 0; levels <= 2; ++levels) {
    const std::string size = std::to_string(workload(levels).source.triangle_count());
    for (const Energy energy : {Energy::frobenius, Energy::similarity})
      for (const std::optional<global::SparseBackEnd> back_end : back_ends) {
        const std::string name = global::to_string(energy) + "/" + size;
        const std::string prefix = back_end ? "backend_" : "scale_";
        const std::string suffix = !back_end                                     ? ""
                                   : *back_end == global::SparseBackEnd::cholmod ? "/cholmod"
                                                                                 : "/simplicial";
        std::vector<std::pair<std::string, decltype(&frame)>> kinds = {{prefix + "setup/", set_up},
                                                                       {prefix + "frame/", frame}};
        if (!back_end) kinds.emplace_back("batch_frames/", frames_batched);
        // three repetitions of at least half a second each (one iteration at 1M): the machine is shared
        for (const auto& [kind, function] : kinds)
          benchmark::RegisterBenchmark((kind + name + suffix).c_str(), function, energy, levels, back_end)
              ->Unit(benchmark::kMillisecond)
              ->MinTime(0.5)
              ->Repetitions(3)
              ->ReportAggregatesOnly(true);
      }
  }
}

}  // namespace
}  // namespace affinterp

int main(int argc, char** argv) {
  affinterp::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
