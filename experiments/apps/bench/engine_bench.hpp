#pragma once
// What the global engine's benchmarks (bench_interp, bench_scale, bench_cli_scale) share: the CLI's options, a
// pair's frame form assembled as the engine assembles it, for timing the sparse system itself, and batches of
// consecutive frames through the batch call.
#include "theory/global/frame_assembly.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/local_paths.hpp"

#include <benchmark/benchmark.h>

#include <optional>
#include <string>

namespace affinterp::bench {

/// The options of `affinterp interpolate` for `energy`: area weights, the straight barycentre locus and, for the
/// energies that need one, the default gauge edge; on the named sparse back-end, or the one the engine picks.
global::InterpolationOptions cli_options(global::Energy energy, const global::Mesh& source, const global::Mesh& target,
                                         std::optional<global::SparseBackEnd> back_end = std::nullopt);

/// The local paths of (source, target) on consistent rotation branches and the frame assembly over them.
class AssembledPair {
 public:
  AssembledPair(const global::Mesh& source, const global::Mesh& target, const global::InterpolationOptions& options);
  const global::FrameAssembly& assembly() const { return *assembly_; }

 private:
  global::LocalPaths paths_;
  std::optional<global::FrameAssembly> assembly_;
};

/// The benchmark loop over batches of 8 consecutive frames, t = (k mod 60 + ½)/60, one vertices_at(times) call
/// each, with the counter `rate` in frames per second (the amortised rate).
void time_batches(benchmark::State& state, const global::Interpolation& interpolation, const std::string& rate);

}  // namespace affinterp::bench
