#pragma once
// The figure of the engine's cost against mesh size: time (ms) and memory (MB) against triangles, log-log
// (plots/engine_scale_curve.hpp), the engine as it chooses and each back-end's set-up and frames, each line titled
// with its fitted exponent, the targets as horizontal lines.
#include "experiments/claims/context.hpp"
#include "experiments/measurements/engine_scale.hpp"

#include <string>
#include <vector>

namespace affinterp::measurements {

/// Draws `scale` as engine-scale.png and .svg under the settings' figure folder; returns their references.
std::vector<std::string> draw_cost_curve(const claims::RunSettings& settings, const EngineScale& scale);

}  // namespace affinterp::measurements
