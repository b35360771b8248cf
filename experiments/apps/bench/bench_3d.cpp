// bench_3d: the 3D engine (theory/global3) on a surface of about 57,000 triangles: the cat of Sumner and Popović
// ("Deformation transfer for triangle meshes", SIGGRAPH 2004), cat-0 → cat-4 subdivided once (57,640 triangles),
// when ../shared/data has it, else CGAL's elephant (libcgal-demo) → its twist, subdivided twice (88,928 triangles).
// 3d/setup: Interpolation3's set-up (E^F, exp-log: decompositions, branches, factorisation); 3d/frame-1-thread one
// frame at a time on one thread (CPU time), 3d/frame-2-threads on two (wall time); 3d/frame-parts the same frame with
// its parts as counters (local maps with the exponential, right-hand side, solve; FrameTimings); 3d/blend3 one frame
// of the N-way blend of three poses (cat-0, cat-4, cat-7; or the elephant's rest, bend, twist) on one thread,
// 3d/blend3-2-threads on two (wall time); 3d/arap-step one as-rigid-as-possible step on the middle frame
// (arap_refinement3.hpp: what each of arap_iterations adds to a frame), one thread; 3d/stand-in the deformation
// application's pipeline (theory/deformation, one thread) on the same pair; 3d/app/<exp> a frame of Interpolation3 with
// another symmetric exponential of thesis ch. 3 (the application claim's ratio, measured in the real engine).
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/bench/speed_figures.hpp"
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "theory/deformation/deformation.hpp"
#include "theory/global3/arap_refinement3.hpp"
#include "theory/global3/blend3.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/sym3/algorithms.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::bench {
namespace {

constexpr double kMinSeconds = 0.2;
using global3::Mesh3;

/// Three poses of one surface, each subdivided as said above; nullopt when neither the cat nor CGAL's data is here.
const std::optional<std::vector<Mesh3>>& poses() {
  static const std::optional<std::vector<Mesh3>> loaded = []() -> std::optional<std::vector<Mesh3>> {
    std::vector<Mesh3> out;
    if (auto cat = shapes3d::cat_poses({0, 4, 7})) {
      for (const Mesh3& pose : *cat) out.push_back(shapes3d::subdivided(pose));
      return out;
    }
    auto elephant = shapes3d::elephant_poses(std::filesystem::temp_directory_path() / "affinterp-cgal-demo");
    if (!elephant) return std::nullopt;
    for (const Mesh3& pose : {(*elephant)[0], (*elephant)[2], (*elephant)[1]})
      out.push_back(shapes3d::subdivided(shapes3d::subdivided(pose)));
    return out;
  }();
  return loaded;
}

bool skip_without_poses(benchmark::State& state) {
  if (poses()) return false;
  state.SkipWithError("neither ../shared/data/meshes3d/cat nor libcgal-demo's data archive is present");
  return true;
}

/// The counters every benchmark reports: the mesh's size and the time of one iteration (a set-up or a frame; CPU
/// time, wall time under UseRealTime), which the report's 3D table reads.
void count_triangles(benchmark::State& state) {
  state.counters["triangles"] = static_cast<double>((*poses())[0].element_count());
  state.counters["ns_per_iteration"] = ns_per_item(1);
}

void setup(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  for (auto _ : state) {
    global3::Interpolation3 engine((*poses())[0], (*poses())[1]);
    benchmark::DoNotOptimize(&engine);
  }
  count_triangles(state);
}

/// The engine named `key` (frame threads and exponential), set up on its first use and kept for the program.
const global3::Interpolation3& engine(const std::string& key, std::size_t threads, const sym3::SymExpBatch& exp = {}) {
  static std::map<std::string, std::unique_ptr<global3::Interpolation3>> engines;
  auto& slot = engines[key];
  if (!slot) {
    global3::Interpolation3Options options;
    options.frame_threads = threads;
    options.exp = exp;
    slot = std::make_unique<global3::Interpolation3>((*poses())[0], (*poses())[1], options);
  }
  return *slot;
}

void frames_of(benchmark::State& state, const global3::Interpolation3& interpolation) {
  const double times[] = {0.25, 0.5, 0.75};
  std::size_t k = 0;
  Eigen::Matrix3Xd v;
  for (auto _ : state) {
    v = interpolation.vertices_at(times[k++ % 3]);
    benchmark::DoNotOptimize(v.data());
  }
  state.counters["finite_vertices"] = static_cast<double>(v.array().isFinite().colwise().all().count());
  count_triangles(state);
}

void frame(benchmark::State& state, std::size_t threads) {
  if (skip_without_poses(state)) return;
  frames_of(state, engine("threads " + std::to_string(threads), threads));
}

void frame_parts(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  const global3::Interpolation3& one = engine("threads 1", 1);
  global3::FrameTimings parts, sum;
  for (auto _ : state) {
    Eigen::Matrix3Xd v = one.vertices_at(0.5, parts);
    benchmark::DoNotOptimize(v.data());
    sum.local_maps += parts.local_maps, sum.right_hand_side += parts.right_hand_side, sum.solve += parts.solve;
  }
  const auto per_frame_ms = [&](double seconds) { return 1e3 * seconds / static_cast<double>(state.iterations()); };
  state.counters["local_maps_ms"] = per_frame_ms(sum.local_maps);
  state.counters["right_hand_side_ms"] = per_frame_ms(sum.right_hand_side);
  state.counters["solve_ms"] = per_frame_ms(sum.solve);
  count_triangles(state);
}

/// The blend of the three poses on `threads` threads, set up on its first use and kept for the program.
const global3::Blend3& blend_of(std::size_t threads) {
  static std::map<std::size_t, std::unique_ptr<global3::Blend3>> blends;
  auto& slot = blends[threads];
  if (!slot) {
    global3::Blend3Options options;
    options.frame_threads = threads;
    slot = std::make_unique<global3::Blend3>(*poses(), options);
  }
  return *slot;
}

void blend3(benchmark::State& state, std::size_t threads) {
  if (skip_without_poses(state)) return;
  const global3::Blend3& blend = blend_of(threads);
  const Eigen::Vector3d weights[] = {{0.2, 0.5, 0.3}, {0.5, 0.25, 0.25}, {0.1, 0.1, 0.8}};
  std::size_t k = 0;
  for (auto _ : state) {
    Eigen::Matrix3Xd v = blend.vertices_at(Eigen::VectorXd(weights[k++ % 3]));
    benchmark::DoNotOptimize(v.data());
  }
  count_triangles(state);
}

void arap_step(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  const global3::Interpolation3& one = engine("threads 1", 1);
  const std::vector<Eigen::Matrix3d> A = one.local_maps_at(0.5);
  const global3::ConstraintTargets3 targets = one.targets_at(0.5);
  const Eigen::Matrix3Xd v = one.vertices_at(0.5);
  for (auto _ : state) {
    Eigen::Matrix3Xd refined = global3::arap_refined(one.system(), A, targets, v, 1, 1);
    benchmark::DoNotOptimize(refined.data());
  }
  count_triangles(state);
}

void stand_in(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  const auto surface = [](const Mesh3& m) { return sym3::Mesh3{m.vertices, m.elements}; };
  static sym3::Deformation3 deformation(surface((*poses())[0]), surface((*poses())[1]));
  const double times[] = {0.25, 0.5, 0.75};
  std::size_t k = 0;
  for (auto _ : state) {
    Eigen::Matrix3Xd v = deformation.interpolate(times[k++ % 3], sym3::exp_batched);
    benchmark::DoNotOptimize(v.data());
  }
  count_triangles(state);
}

void app_frame(benchmark::State& state, const std::string& name, const sym3::SymExpBatch& exp) {
  if (skip_without_poses(state)) return;
  frames_of(state, engine(name, 1, exp));
}

void register_all() {
  auto configure = [](benchmark::internal::Benchmark* b) {
    b->Repetitions(kRepetitions)->DisplayAggregatesOnly(true)->Unit(benchmark::kMillisecond);
  };
  configure(benchmark::RegisterBenchmark("3d/setup", setup)->Iterations(1));
  // Two benchmarks, not one with an argument: the report reads them by name, and merged files drop arguments.
  configure(benchmark::RegisterBenchmark("3d/frame-1-thread", frame, 1)->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/frame-2-threads", frame, 2)->UseRealTime()->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/frame-parts", frame_parts)->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/blend3", blend3, 1)->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/blend3-2-threads", blend3, 2)->UseRealTime()->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/arap-step", arap_step)->MinTime(kMinSeconds));
  configure(benchmark::RegisterBenchmark("3d/stand-in", stand_in)->MinTime(kMinSeconds));
  for (const auto& variant : sym3::exp_variants())
    if ("app/" + variant.name == names::app_diag || "app/" + variant.name == names::app_improved_sd)
      configure(benchmark::RegisterBenchmark(("3d/app/" + variant.name).c_str(), app_frame, variant.name, variant.exp)
                    ->MinTime(kMinSeconds));
}

}  // namespace
}  // namespace affinterp::bench

int main(int argc, char** argv) {
  affinterp::bench::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
