#pragma once
// Building outlines for shapes::triangulate from straight pieces and circular arcs.
#include "experiments/inputs/shapes/triangulate.hpp"

#include <cmath>

namespace affinterp::shapes {

/// Appends `pieces` + 1 points of the arc of `centre` and `radius` from angle `from` to `to` (radians;
/// decreasing angles run clockwise).
inline void append_arc(Outline& outline, const Eigen::Vector2d& centre, double radius, double from, double to,
                       int pieces) {
  for (int j = 0; j <= pieces; ++j) {
    const double angle = from + (to - from) * j / pieces;
    outline.push_back(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
}

}  // namespace affinterp::shapes
