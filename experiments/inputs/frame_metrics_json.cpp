#include "experiments/inputs/frame_metrics_json.hpp"

#include <cmath>

namespace affinterp::io {

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json metrics_json(const global::FrameMetrics& m) {
  return {{"flipped_triangles", m.flipped_triangles},
          {"min_det", finite_or_null(m.min_det)},
          {"max_det", finite_or_null(m.max_det)},
          {"max_distortion", finite_or_null(m.max_distortion)},
          {"mean_distortion", finite_or_null(m.mean_distortion)},
          {"area_ratio", finite_or_null(m.area_ratio)}};
}

nlohmann::json metrics3_json(const global3::FrameMetrics3& m, bool near_folds) {
  nlohmann::json entry = {{"inverted_elements", m.inverted_elements},
                          {"min_ratio", finite_or_null(m.min_ratio)},
                          {"max_ratio", finite_or_null(m.max_ratio)},
                          {"max_distortion", finite_or_null(m.max_distortion)},
                          {"mean_distortion", finite_or_null(m.mean_distortion)},
                          {"measure_ratio", finite_or_null(m.measure_ratio)}};
  if (near_folds) entry["inverted_near_folds"] = m.inverted_near_folds;
  return entry;
}

}  // namespace affinterp::io
