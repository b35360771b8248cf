// Speed of the global interpolation engine (Kaji Appendix, "Efficiency"): set-up (local maps, polar
// decompositions, rotation branches, sparsity pattern, symbolic analysis, first factorisation) and one
// frame (v(t) for a new t) per energy, on the octopus mesh of ../shared (66,527 triangles) bent by a
// known curl — or, when ../shared is absent, on the project's generated man meshed by CGAL to a similar
// size, 65,326 triangles (the benchmark names say which): an unstructured mesh of an organic outline like
// the octopus, whose E^R frame costs about the same as the octopus's, where a
// structured 543 × 61 grid strip of that size, the earlier stand-in, cost markedly more. The baseline
// refactorises from scratch every frame (symbolic + numeric, as common public implementations do),
// measured in the same run; batch_frames/<energy> computes 8 frames at once (vertices_at(times)), and
// frame_rhs, frame_assembly, frame_factor and frame_solve time the parts of an E^F and an E^R frame.
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/apps/bench/engine_bench.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/curl.hpp"
#include "experiments/inputs/shapes/man.hpp"
#include "theory/global/frame_assembly.hpp"
#include "theory/global/hermitian_form.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/parallel_ranges.hpp"
#include "theory/global/sparse_minimiser.hpp"

#include <benchmark/benchmark.h>

#include <Eigen/SparseCholesky>

#include <complex>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

namespace affinterp {
namespace {

using global::Energy;

struct Workload {
  std::string name;
  global::Mesh source, target;
};

/// The source bent by a circular curl through one radian along its width (a known deformation).
const Workload& workload() {
  static const Workload w = [] {
    namespace fs = std::filesystem;
    const fs::path shared = AFFINTERP_SOURCE_DIR "/../shared/data/meshes";
    Workload load;
    if (fs::exists(shared / "octopus.obj")) {
      load.name = "octopus", load.source = io::read_mesh(shared / "octopus.obj");
    } else {
      load.name = "man-65k", load.source = shapes::man(0.0137);
    }
    const Eigen::Vector2d low = load.source.vertices.rowwise().minCoeff(),
                          high = load.source.vertices.rowwise().maxCoeff();
    const Eigen::Vector2d centre_left(low.x(), (low.y() + high.y()) / 2);
    const shapes::Curl curl{high.x() - low.x(), 1.0, 1};
    load.target = load.source;
    load.target.vertices = curl.apply(Eigen::Matrix2Xd(load.source.vertices.colwise() - centre_left), 1);
    return load;
  }();
  return w;
}

global::InterpolationOptions options_for(Energy energy) {
  const global::Mesh& P = workload().source;
  Eigen::Index left = 0, right = 0;
  for (Eigen::Index k = 1; k < P.vertex_count(); ++k) {
    if (P.vertices(0, k) < P.vertices(0, left)) left = k;
    if (P.vertices(0, k) > P.vertices(0, right)) right = k;
  }
  global::InterpolationOptions options;
  options.energy = energy;
  options.constraints.pinned = {{left, 1.0}, {right, 1.0}};
  return options;
}

void set_up(benchmark::State& state, Energy energy) {
  const Workload& w = workload();
  for (auto _ : state) {
    global::Interpolation interpolation(w.source, w.target, options_for(energy));
    benchmark::DoNotOptimize(&interpolation);
  }
  state.counters["triangles"] = static_cast<double>(w.source.triangle_count());
}

void frame(benchmark::State& state, Energy energy) {
  const Workload& w = workload();
  const global::Interpolation interpolation(w.source, w.target, options_for(energy));
  int k = 0;
  for (auto _ : state) {
    const double t = (k++ % 60 + 0.5) / 60;
    benchmark::DoNotOptimize(interpolation.vertices_at(t).data());
  }
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // A label, not a counter: a counter that is 0 in every repetition gets a NaN coefficient of variation,
  // which Google Benchmark writes into its JSON as a bare NaN that no JSON parser accepts.
  state.SetLabel(interpolation.factored_once() ? "factored once" : "refactorised per frame");
}

/// 8 frames per iteration through the batch call vertices_at(times), in parallel on the machine's cores; its
/// frames/s is the amortised rate.
void frames_batched(benchmark::State& state, Energy energy) {
  const Workload& w = workload();
  bench::time_batches(state, global::Interpolation(w.source, w.target, options_for(energy)), "frames/s");
}

/// The parts of a frame as vertices_at(t) runs them, on the engine's back-end for the size and the threads it gives
/// a frame (parallel_ranges.hpp): what a frame's time is made of. Where H(t) changes with t
/// (E^R), its assembly, numeric factorisation and solve; where it does not (E^F), the right-hand side and the solve
/// of its two real columns.
enum class FramePart { right_hand_side, assembly, factorisation, solve };

void frame_part(benchmark::State& state, Energy energy, FramePart part) {
  const Workload& w = workload();
  const bench::AssembledPair pair(w.source, w.target, options_for(energy));
  const global::FrameAssembly& assembly = pair.assembly();
  global::FrameAssembly::SparseMatrix H = assembly.pattern();
  const std::size_t threads = global::frame_threads(static_cast<std::size_t>(H.rows()), !assembly.isotropic());
  assembly.matrix_at(0.5, H);
  const Eigen::VectorXcd b = assembly.right_hand_side_at(0.5, threads);
  global::SparseMinimiser<std::complex<double>> minimiser;
  global::SparseMinimiser<double> fixed;
  Eigen::MatrixXd xy(b.size(), 2);
  if (assembly.isotropic()) {
    Eigen::SparseMatrix<double> L = H.real();
    L.makeCompressed();
    fixed.analyse(L, assembly.dense_term());
    fixed.factorise(L, threads);
    xy << b.real(), b.imag();
  } else {
    minimiser.analyse(H, assembly.dense_term());
    minimiser.factorise(H, threads);
  }
  int k = 0;
  for (auto _ : state) {
    const double t = (k++ % 60 + 0.5) / 60;
    if (part == FramePart::right_hand_side) benchmark::DoNotOptimize(assembly.right_hand_side_at(t, threads).data());
    if (part == FramePart::assembly) assembly.matrix_at(t, H, threads);
    if (part == FramePart::factorisation) minimiser.factorise(H, threads);
    if (part == FramePart::solve && assembly.isotropic()) benchmark::DoNotOptimize(fixed.solve(xy, threads).data());
    if (part == FramePart::solve && !assembly.isotropic()) benchmark::DoNotOptimize(minimiser.solve(b, threads).data());
  }
  state.counters["threads"] = static_cast<double>(threads);
}

/// The baseline: the real 2n × 2n form G(t) = realified H(t), analysed and factorised from scratch for every
/// frame. Building G is not timed, so the baseline's assembly is free: the ratio to it understates ours.
void frame_refactor(benchmark::State& state, Energy energy) {
  const Workload& w = workload();
  const bench::AssembledPair pair(w.source, w.target, options_for(energy));
  const global::FrameAssembly& assembly = pair.assembly();
  global::FrameAssembly::SparseMatrix H = assembly.pattern();
  int k = 0;
  for (auto _ : state) {
    const double t = (k++ % 60 + 0.5) / 60;
    state.PauseTiming();
    assembly.matrix_at(t, H);
    const Eigen::SparseMatrix<double> G = global::realified(H);
    const Eigen::VectorXcd b = assembly.right_hand_side_at(t);
    const Eigen::VectorXd r =
        Eigen::Map<const Eigen::VectorXd>(reinterpret_cast<const double*>(b.data()), 2 * b.size());
    state.ResumeTiming();
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(G);
    benchmark::DoNotOptimize(Eigen::VectorXd(ldlt.solve(r)).data());
  }
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

/// Ten runs of at least a second each (kRepetitions), every one kept in the JSON file for the bootstrap
/// intervals of the targets, reported as mean, median and spread: the machine is shared.
void repeated(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->MinTime(1.0)->Repetitions(bench::kRepetitions)->DisplayAggregatesOnly(true);
}

void register_all() {
  const std::string mesh = workload().name;
  for (const Energy energy : {Energy::F, Energy::R, Energy::S, Energy::blend}) {
    const std::string e = global::to_string(energy);
    benchmark::RegisterBenchmark(("setup/" + e + "/" + mesh).c_str(), set_up, energy)->Apply(repeated);
    benchmark::RegisterBenchmark(("frame/" + e + "/" + mesh).c_str(), frame, energy)->Apply(repeated);
  }
  for (const Energy energy : {Energy::F, Energy::R}) {
    const std::string e = global::to_string(energy);
    benchmark::RegisterBenchmark(("frame_refactor/" + e + "/" + mesh).c_str(), frame_refactor, energy)->Apply(repeated);
    benchmark::RegisterBenchmark(("batch_frames/" + e + "/" + mesh).c_str(), frames_batched, energy)->Apply(repeated);
  }
  const std::pair<FramePart, const char*> rhs{FramePart::right_hand_side, "frame_rhs"},
      assembly{FramePart::assembly, "frame_assembly"}, factor{FramePart::factorisation, "frame_factor"},
      solve{FramePart::solve, "frame_solve"};
  for (const auto& [energy, parts] :
       {std::pair{Energy::F, std::vector{rhs, solve}}, {Energy::R, std::vector{assembly, factor, solve}}})
    for (const auto& [part, name] : parts)
      benchmark::RegisterBenchmark((std::string(name) + "/" + global::to_string(energy) + "/" + mesh).c_str(),
                                   frame_part, energy, part)
          ->Apply(repeated);
}

}  // namespace
}  // namespace affinterp

int main(int argc, char** argv) {
  affinterp::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
