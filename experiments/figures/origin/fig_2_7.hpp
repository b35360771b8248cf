#pragma once
// Thesis Fig. 2.7: the global interpolation of the two triangles with the local interpolations taken about
// the world origin (red) and about each triangle's barycentre (green).
#include "experiments/claims/context.hpp"
#include "theory/origin/two_triangles.hpp"

#include <string>
#include <vector>

namespace affinterp::figures {

struct Fig27 {
  std::vector<std::string> files;  ///< the report's references to the files drawn
  double largest_gap = 0;          ///< max over frames and vertices of |v_red − v_green|
};

/// Draws frames t = 0, 1/4, …, 1 of both interpolations side by side, the target triangles A_i(T_i)
/// dashed in the last frame.
Fig27 draw_fig_2_7(const claims::RunContext& ctx, const origin::TwoTriangles& config);

}  // namespace affinterp::figures
