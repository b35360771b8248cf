#pragma once
// metrics.json's quality numbers of one frame, in the vocabulary `affinterp interpolate` and `affinterp blend`
// write and the Python module returns (Interpolation.metrics_at, Blend.metrics_at): the plane's
// (theory/global/metrics.hpp) and space's (theory/global3/frame_metrics3.hpp). A number that is not finite (a
// singular element's distortion) is null.
#include "theory/global/metrics.hpp"
#include "theory/global3/frame_metrics3.hpp"

#include <nlohmann/json.hpp>

namespace affinterp::io {

/// x, or null when x is not finite.
nlohmann::json finite_or_null(double x);

/// flipped_triangles, min_det, max_det, max_distortion, mean_distortion, area_ratio.
nlohmann::json metrics_json(const global::FrameMetrics& metrics);

/// inverted_elements, min_ratio, max_ratio, max_distortion, mean_distortion, measure_ratio; with `near_folds`,
/// also inverted_near_folds (those of them at or beside the folds of the target or of a pose).
nlohmann::json metrics3_json(const global3::FrameMetrics3& metrics, bool near_folds);

}  // namespace affinterp::io
