#pragma once
// The engine's targets at a million triangles on 2 cores, and each decided on the spread of its runs: a target
// "at most the limit" is met (reproduced) when every run meets it, missed (not-reproduced) when none does,
// undecided (inconclusive) otherwise or without a spread (speed_verdict.hpp's interval rule on [least, largest]).
// With five i.i.d. runs the least and the largest bracket the median of runs with probability 1 − 2 · 2⁻⁵ ≈ 94%,
// whatever their distribution (order statistics), so a verdict does not flip with the machine's noise as one on
// the median alone does.
#include "experiments/measurements/engine_scale.hpp"

namespace affinterp::measurements {

/// Set-up ≤ 3 s, E^F ≤ 0.1 s a frame, E^R ≤ 0.6 s a batched frame growing at most 5 times from the size before,
/// peak memory ≤ 2 GB, at 1M triangles.
ScaleTargets scale_targets();

/// Sets scale.growth_R, scale.target_verdicts and scale.verdict (all_of them) from scale.rows at the largest size
/// at or beyond scale.targets.triangles, with where the time goes of each target not met, from the run's own rows
/// of the back-end the engine uses at that size; leaves the verdicts empty when no size reaches it.
void decide_targets(EngineScale& scale);

}  // namespace affinterp::measurements
