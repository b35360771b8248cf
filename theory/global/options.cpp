#include "theory/global/options.hpp"

#include "theory/global/refused_problem.hpp"

#include <cmath>
#include <string>

namespace affinterp::global {

void require_valid_options(const InterpolationOptions& options, Eigen::Index triangles) {
  if (!(options.t_begin <= options.t_end) || !std::isfinite(options.t_begin) || !std::isfinite(options.t_end))
    throw RefusedProblem("the time range must be finite with t_begin <= t_end");
  const auto in_unit_interval = [](double w) { return w >= 0 && w <= 1; };
  if (!in_unit_interval(options.blend_weight)) throw RefusedProblem("the blend weight w must lie in [0, 1]");
  if (options.blend_weights.size() == 0) return;
  if (options.blend_weights.size() != triangles)
    throw RefusedProblem("the blend needs one weight w_i per triangle (" + std::to_string(triangles) + "), got " +
                         std::to_string(options.blend_weights.size()));
  if (!options.blend_weights.unaryExpr(in_unit_interval).all())
    throw RefusedProblem("blend weights w_i must lie in [0, 1]");
}

}  // namespace affinterp::global
