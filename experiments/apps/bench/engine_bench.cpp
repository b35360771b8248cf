#include "experiments/apps/bench/engine_bench.hpp"

#include "theory/global/constraint_terms.hpp"
#include "theory/global/gauge.hpp"
#include "theory/global/rotation_branch.hpp"

#include <vector>

namespace affinterp::bench {
namespace {

global::LocalPaths consistent_paths(const global::Mesh& source, const global::Mesh& target,
                                    global::LocalHomotopy homotopy) {
  std::vector<Eigen::Matrix2d> A;
  Eigen::VectorXd theta(source.triangle_count());
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) {
    global::Corners<double> p, q;
    for (int c = 0; c < 3; ++c) p.col(c) = source.corner(i, c), q.col(c) = target.corner(i, c);
    A.push_back(global::linear_part(p, q));
    theta[i] = global::principal_polar_angle(A.back());
  }
  return global::LocalPaths(A, homotopy, global::consistent_angles(source.triangles, theta));
}

}  // namespace

global::InterpolationOptions cli_options(global::Energy energy, const global::Mesh& source, const global::Mesh& target,
                                         std::optional<global::SparseBackEnd> back_end) {
  global::InterpolationOptions options;
  options.energy = energy;
  options.back_end = back_end;
  options.area_weighted = true;
  options.constraints.barycentre = global::BarycentreLocus{};
  if (const auto edge = global::default_edge_direction(source, target, options))
    options.constraints.edges.push_back(*edge);
  return options;
}

AssembledPair::AssembledPair(const global::Mesh& source, const global::Mesh& target,
                             const global::InterpolationOptions& options)
    : paths_(consistent_paths(source, target, options.homotopy)) {
  assembly_.emplace(source, target, options, paths_, nullptr,
                    global::constraint_terms(options.constraints, source, target, paths_));
}

void time_batches(benchmark::State& state, const global::Interpolation& interpolation, const std::string& rate) {
  constexpr int batch = 8;
  int k = 0;
  for (auto _ : state) {
    std::vector<double> times;
    for (int j = 0; j < batch; ++j) times.push_back((k++ % 60 + 0.5) / 60);
    benchmark::DoNotOptimize(interpolation.vertices_at(times).data());
  }
  state.counters[rate] = benchmark::Counter(batch, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace affinterp::bench
