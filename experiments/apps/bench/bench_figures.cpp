// What the figures cost a user of `affinterp interpolate`: the octopus of ../shared (66,527
// triangles) curled by half a turn (shapes::Curl, θ_end = π), 17 frames, run end to end as a process with
// its default outputs (OBJ frames, metrics.json, filmstrip PNG + SVG, animated GIF, viewer.html) and with
// --no-figures. Each iteration runs both, one after the other, so that the load of a shared machine weighs
// on both alike; the time is the default run's wall time, and the counters give the --no-figures run's,
// their ratio (the target: at most 2) and each run's peak resident memory. Without ../shared, the
// project's generated man meshed to a similar size (65,326 triangles) stands in (the name says which).
//
// Why the figures are drawn in-process (Cairo, giflib): that keeps the default run close to the --no-figures
// run, where one gnuplot session drawing every GIF frame through its `gif animate` terminal, and before it
// pngcairo frames joined by ImageMagick's convert, made it several times slower (this benchmark measures the
// ratio; the commit that added this file records the alternatives' figures).
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/apps/bench/cli_process.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/curl.hpp"
#include "experiments/inputs/shapes/man.hpp"

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace affinterp {
namespace {

namespace fs = std::filesystem;

struct Workload {
  std::string name;
  fs::path folder, source, target;
  Eigen::Index triangles = 0;
};

/// The source and its curl written as OBJ files once.
const Workload& workload() {
  static const Workload w = [] {
    const fs::path shared = AFFINTERP_SOURCE_DIR "/../shared/data/meshes";
    Workload load;
    load.folder = fs::temp_directory_path() / ("affinterp_bench_figures_" + std::to_string(getpid()));
    global::Mesh source;
    if (fs::exists(shared / "octopus.obj")) {
      load.name = "octopus", source = io::read_mesh(shared / "octopus.obj");
    } else {
      load.name = "man-65k", source = shapes::man(0.0137);
    }
    const Eigen::Vector2d low = source.vertices.rowwise().minCoeff(), high = source.vertices.rowwise().maxCoeff();
    const shapes::Curl curl{high.x() - low.x(), std::numbers::pi, 1};
    global::Mesh target = source;
    // About the top edge: every point lies on the outer side of the curl, so no triangle flips (about
    // the middle, the octopus's half height would exceed the curl's radius L/π).
    target.vertices = curl.apply(Eigen::Matrix2Xd(source.vertices.colwise() - Eigen::Vector2d(low.x(), high.y())), 1);
    fs::create_directories(load.folder);
    load.source = load.folder / "source.obj", load.target = load.folder / "target.obj";
    io::write_obj(source, load.source);
    io::write_obj(target, load.target);
    load.triangles = source.triangle_count();
    return load;
  }();
  return w;
}

/// `affinterp interpolate` on the workload, 17 frames, into a fresh folder; wall time and peak memory.
bench::ProcessRun interpolate(bool figures) {
  const Workload& w = workload();
  const fs::path out = w.folder / (figures ? "default" : "no-figures");
  fs::remove_all(out);
  std::vector<std::string> args{"interpolate", "--source", w.source.string(), "--target",  w.target.string(),
                                "--frames",    "17",       "--out",           out.string()};
  if (!figures) args.push_back("--no-figures");
  return bench::run_cli(AFFINTERP_CLI, args);
}

void default_against_no_figures(benchmark::State& state) {
  double with = 0, without = 0, peak_with = 0, peak_without = 0;
  for (auto _ : state) {
    const bench::ProcessRun plain = interpolate(false), full = interpolate(true);
    state.SetIterationTime(full.seconds);
    with += full.seconds, without += plain.seconds;
    peak_with = std::max(peak_with, full.peak_mb), peak_without = std::max(peak_without, plain.peak_mb);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["no_figures_ms"] = 1e3 * without / n;
  state.counters["ratio"] = with / without;
  state.counters["peak_MB"] = peak_with;
  state.counters["no_figures_peak_MB"] = peak_without;
  state.counters["triangles"] = static_cast<double>(workload().triangles);
}

}  // namespace
}  // namespace affinterp

int main(int argc, char** argv) {
  const std::string name = "interpolate/default_vs_no_figures/17_frames/" + affinterp::workload().name;
  benchmark::RegisterBenchmark(name.c_str(), affinterp::default_against_no_figures)
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->Iterations(2)
      ->Repetitions(3)
      ->ReportAggregatesOnly(true);
  const int status = affinterp::bench::run_benchmarks(argc, argv);
  std::filesystem::remove_all(affinterp::workload().folder);
  return status;
}
