#pragma once
// The global error function of one frame written out as a real quadratic form (Kaji Appendix,
// "Efficiency"); frame_assembly.hpp builds it, Interpolation::quadratic_at returns it.
#include <Eigen/Core>

namespace affinterp::global {

/// The quadratic form E(v) = vᵀ G v + vᵀ u + c of one frame, v = (v_1x, v_1y, …, v_nx, v_ny) (Kaji
/// Appendix), with the constraint terms included.
struct FrameQuadratic {
  Eigen::MatrixXd G;  ///< dense: for inspection on small meshes only
  Eigen::VectorXd u;
  double c = 0.0;
};

}  // namespace affinterp::global
