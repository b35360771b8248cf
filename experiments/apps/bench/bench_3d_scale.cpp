// bench_3d_scale: the 3D engine (theory/global3, E^F, exp-log) at the scale, a surface of over a million
// triangles: CGAL's elephant (libcgal-demo) subdivided four times (1,422,848 triangles) towards its twist.
// 3d-scale/setup the set-up, 3d-scale/frame one frame at a time on two threads (wall time), each with the process's
// peak resident memory after it (peak_rss_mb). Three repetitions: a scale study, run by reproduce.sh --scale only.
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "theory/global3/interpolation3.hpp"

#include <sys/resource.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace affinterp::bench {
namespace {

using global3::Mesh3;

/// The elephant's rest and twisted poses, each subdivided four times; nullopt without libcgal-demo.
const std::optional<std::vector<Mesh3>>& poses() {
  static const std::optional<std::vector<Mesh3>> loaded = []() -> std::optional<std::vector<Mesh3>> {
    auto elephant = shapes3d::elephant_poses(std::filesystem::temp_directory_path() / "affinterp-cgal-demo");
    if (!elephant) return std::nullopt;
    std::vector<Mesh3> out;
    for (Mesh3 pose : {(*elephant)[0], (*elephant)[2]}) {
      for (int k = 0; k < 4; ++k) pose = shapes3d::subdivided(pose);
      out.push_back(std::move(pose));
    }
    return out;
  }();
  return loaded;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024;  // Linux reports kilobytes
}

/// The counters the report reads (engine3_scale.hpp): the mesh's size, the time of one iteration (wall time, as
/// both benchmarks use real time) and the peak memory so far.
void report(benchmark::State& state) {
  state.counters["triangles"] = static_cast<double>((*poses())[0].element_count());
  state.counters["ns_per_iteration"] = ns_per_item(1);
  state.counters["peak_rss_mb"] = peak_rss_mb();
}

bool skip_without_poses(benchmark::State& state) {
  if (poses()) return false;
  state.SkipWithError("libcgal-demo's data archive is not present");
  return true;
}

void setup(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  for (auto _ : state) {
    global3::Interpolation3 engine((*poses())[0], (*poses())[1]);
    benchmark::DoNotOptimize(&engine);
  }
  report(state);
}

void frame(benchmark::State& state) {
  if (skip_without_poses(state)) return;
  global3::Interpolation3Options options;
  options.frame_threads = 2;
  static const global3::Interpolation3 engine((*poses())[0], (*poses())[1], options);
  const double times[] = {0.25, 0.5, 0.75};
  std::size_t k = 0;
  for (auto _ : state) {
    Eigen::Matrix3Xd v = engine.vertices_at(times[k++ % 3]);
    benchmark::DoNotOptimize(v.data());
  }
  report(state);
}

void register_all() {
  constexpr int repetitions = 3;
  benchmark::RegisterBenchmark("3d-scale/setup", setup)
      ->Iterations(1)
      ->Repetitions(repetitions)
      ->Unit(benchmark::kSecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("3d-scale/frame", frame)
      ->Iterations(4)
      ->Repetitions(repetitions)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

}  // namespace
}  // namespace affinterp::bench

int main(int argc, char** argv) {
  affinterp::bench::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
