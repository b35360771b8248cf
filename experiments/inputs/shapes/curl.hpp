#pragma once
// A known curl of a straight bar, with its exact in-between poses. The bar [0, L] × [−h/2, h/2] is
// wound so that its centre line keeps its length and turns by the tangent angle θ(s) = θ_end (s/L)^p:
//   c_t(s) = ∫_0^s (cos tθ(u), sin tθ(u)) du,   (s, y) ↦ c_t(s) + y n_t(s),   n_t = (−sin tθ(s), cos tθ(s)).
// t = 0 is the straight bar and t = 1 the target; at t every cross-section is turned by exactly tθ(s)
// (the end by t·θ_end, beyond 2π when θ_end > 2π): the answer a rigid interpolation should give.
#include <Eigen/Core>

namespace affinterp::shapes {

struct Curl {
  double length;     ///< L
  double theta_end;  ///< the end's turn θ(L)
  double power;      ///< p: 1 bends into a circular arc, 2 curls into a tightening spiral

  double theta(double s) const;
  /// The image of the bar point (s, y) at time t.
  Eigen::Vector2d apply(const Eigen::Vector2d& point, double t) const;
  /// The images of all columns.
  Eigen::Matrix2Xd apply(const Eigen::Matrix2Xd& points, double t) const;
};

}  // namespace affinterp::shapes
