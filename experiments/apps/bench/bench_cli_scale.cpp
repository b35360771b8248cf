// The CLI as fast as the engine at a million triangles: `affinterp interpolate` on the shape pair
// strip-spiral at 2000 × 250 quads (1,000,000 triangles, 18.8 × 2 rolled 1.5 turns), with --format npy
// --no-figures --metrics none, run as a process for 2 frames and for 2 + extra_frames(energy), one after the
// other in each iteration; a frame through the CLI, writing included, costs the difference over the extra frames
// (reading the meshes and the set-up cancel). E^F's frames are ten times cheaper than E^R's, so it takes 32
// extra frames, E^R 8: with 8, E^F's difference (a small part of a run) moved by a third from run to run. Beside it,
// in the same process, the engine's own frame on the same pair: vertices_at(times) of 8 frames, per frame (the CLI
// solves its frames in batches too). The report (experiments/measurements/engine_cli.hpp) sets the one against the
// other: the target is at most 1.3 times, judged on the bootstrap interval of the ratio of medians over the
// repetitions. For E^F, cli_frame_memory repeats the CLI runs writing into /dev/shm: the difference is what the
// file system costs.
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/apps/bench/cli_process.hpp"
#include "experiments/apps/bench/engine_bench.hpp"
#include "experiments/bench/measured.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/rolled_strip.hpp"
#include "theory/global/interpolation.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace affinterp {
namespace {

namespace fs = std::filesystem;
using global::Energy;

constexpr int cols = 2000, rows = 250;
/// Frames of the short CLI run and of the engine's batch.
constexpr int short_run = 2, batch = 8;

/// The long CLI run's frames beyond the short run's.
int extra_frames(Energy energy) { return energy == Energy::F ? 32 : 8; }

struct Workload {
  shapes::Spiral pair;
  fs::path folder, source, target;
};

/// The spiral, and its OBJ files written once (as `affinterp shapes strip-spiral --quads 2000x250` writes them).
const Workload& workload() {
  static const Workload w = [] {
    Workload load{shapes::spiral(cols, rows),
                  fs::temp_directory_path() / ("affinterp_bench_cli_scale_" + std::to_string(getpid())),
                  {},
                  {}};
    fs::create_directories(load.folder);
    load.source = load.folder / "source.obj", load.target = load.folder / "target.obj";
    io::write_obj(load.pair.source, load.source);
    io::write_obj(load.pair.target, load.target);
    return load;
  }();
  return w;
}

/// Where the memory variant writes its frames: a RAM-backed file system, when this machine has one.
const fs::path memory_folder = "/dev/shm";

/// `affinterp interpolate` with `energy` for `frames` frames into a fresh folder under `parent`: its wall time.
double interpolate_seconds(Energy energy, int frames, const fs::path& parent) {
  const Workload& w = workload();
  const fs::path out =
      parent / ("affinterp_bench_cli_scale_out_" + std::to_string(getpid()) + "_" + std::to_string(frames));
  fs::remove_all(out);
  const double seconds =
      bench::run_cli(AFFINTERP_CLI, {"interpolate", "--source", w.source.string(), "--target", w.target.string(),
                                     "--energy", global::to_string(energy), "--frames", std::to_string(frames),
                                     "--format", "npy", "--no-figures", "--metrics", "none", "--out", out.string()})
          .seconds;
  fs::remove_all(out);
  return seconds;
}

/// A frame through the CLI writing into `parent`: the temporary folder (a disk, as a user's output), or for
/// cli_frame_memory memory_folder, which leaves the file system's cost of writing 16 bytes a vertex a frame out.
void cli_frame(benchmark::State& state, Energy energy, const fs::path& parent) {
  for (auto _ : state) {
    const double short_seconds = interpolate_seconds(energy, short_run, parent);
    const double long_seconds = interpolate_seconds(energy, short_run + extra_frames(energy), parent);
    state.SetIterationTime((long_seconds - short_seconds) / extra_frames(energy));
  }
  state.counters["triangles"] = static_cast<double>(workload().pair.source.triangle_count());
  state.counters["extra_frames"] = extra_frames(energy);
}

void engine_frame(benchmark::State& state, Energy energy) {
  const shapes::Spiral& s = workload().pair;
  const global::Interpolation interpolation(s.source, s.target, bench::cli_options(energy, s.source, s.target));
  int k = 0;
  for (auto _ : state) {
    std::vector<double> times;
    for (int j = 0; j < batch; ++j) times.push_back((k++ % 60 + 0.5) / 60);
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(interpolation.vertices_at(times).data());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / batch);
  }
  state.counters["triangles"] = static_cast<double>(s.source.triangle_count());
}

/// `frame` (a callable taking the benchmark's state) as a benchmark of manual times, every repetition recorded: the
/// report's ratio takes its interval over them.
template <class Frame>
void register_frame(const std::string& name, Frame frame) {
  benchmark::RegisterBenchmark(name.c_str(), frame)
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->Iterations(1)
      ->Repetitions(static_cast<int>(bench::kMinRepetitions));
}

void register_all() {
  const std::string size = std::to_string(2 * cols * rows);
  for (const Energy energy : {Energy::F, Energy::R}) {
    const std::string name = global::to_string(energy) + "/" + size;
    register_frame("cli_frame/" + name,
                   [energy](benchmark::State& state) { cli_frame(state, energy, fs::temp_directory_path()); });
    // E^F's frames are the cheap ones, where writing weighs: the same runs into memory show how much.
    if (energy == Energy::F && fs::is_directory(memory_folder))
      register_frame("cli_frame_memory/" + name,
                     [energy](benchmark::State& state) { cli_frame(state, energy, memory_folder); });
    register_frame("engine_frame/" + name, [energy](benchmark::State& state) { engine_frame(state, energy); });
  }
}

}  // namespace
}  // namespace affinterp

int main(int argc, char** argv) {
  affinterp::register_all();
  const int status = affinterp::bench::run_benchmarks(argc, argv);
  std::filesystem::remove_all(affinterp::workload().folder);
  return status;
}
