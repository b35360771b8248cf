// bench_app3: the deformation application of thesis §3.4, Fig. 3.3, rebuilt in 3D
// (theory/deformation/deformation.hpp): one frame of the dragon (ChineseDragon-10kv from libcgal-demo,
// subdivided once: 79,976 triangles) interpolated towards its twisted pose, with the per-triangle
// symmetric exponential of each registered algorithm (and the batched one). app/<algorithm> reports
// the CPU time per frame (ns_per_frame) and per triangle (ns_per_triangle), and the finite vertices
// of its last frame (all of them when the frame is sound). Set-up (mesh extraction, polar
// decompositions, logarithms, Cholesky factorisation) is done once, outside the timing, as in an
// interactive tool.
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/inputs/sym3/demo_mesh.hpp"
#include "experiments/inputs/sym3/pose.hpp"
#include "theory/deformation/deformation.hpp"
#include "theory/sym3/exp_batch.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace affinterp::bench {
namespace {

constexpr double kMinSeconds = 0.5;

/// The dragon's deformation, set up on first use; null when the CGAL data archive is absent.
sym3::Deformation3* dragon() {
  static const std::unique_ptr<sym3::Deformation3> deformation = []() -> std::unique_ptr<sym3::Deformation3> {
    const auto mesh = sym3::dragon_mesh(std::filesystem::temp_directory_path() / "affinterp-cgal-data");
    if (!mesh) return nullptr;
    return std::make_unique<sym3::Deformation3>(*mesh, sym3::twisted_pose(*mesh));
  }();
  return deformation.get();
}

void frame(benchmark::State& state, const sym3::SymExpBatch& exp) {
  sym3::Deformation3* deformation = dragon();
  if (!deformation) {
    state.SkipWithError(("the CGAL demo data " + std::string(sym3::cgal_demo_archive) +
                         " is absent: install the Debian package libcgal-demo")
                            .c_str());
    return;
  }
  const double times[] = {0.25, 0.5, 0.75};
  std::size_t k = 0;
  Eigen::Matrix3Xd x;
  for (auto _ : state) {
    x = deformation->interpolate(times[k++ % 3], exp);
    benchmark::DoNotOptimize(x.data());
  }
  // A fast frame is worthless if it is wrong: count the vertices of the last frame that are finite (a
  // count rather than the non-finite one, whose zero mean would make the aggregates' variation NaN).
  state.counters["finite_vertices"] = static_cast<double>(x.array().isFinite().colwise().all().count());
  state.counters["ns_per_frame"] = ns_per_item(1);
  state.counters["ns_per_triangle"] = ns_per_item(deformation->triangle_count());
  state.counters["triangles"] = static_cast<double>(deformation->triangle_count());
}

void register_all() {
  auto configure = [](benchmark::internal::Benchmark* b) {
    b->Repetitions(kRepetitions)->DisplayAggregatesOnly(true)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);
  };
  for (const auto& variant : sym3::exp_variants())
    configure(benchmark::RegisterBenchmark(("app/" + variant.name).c_str(), frame, variant.exp));
}

}  // namespace
}  // namespace affinterp::bench

int main(int argc, char** argv) {
  affinterp::bench::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
