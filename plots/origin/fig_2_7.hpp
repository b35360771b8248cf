#pragma once
// Thesis Fig. 2.7: the global interpolation of the two triangles with the local interpolations taken about
// the world origin (red) and about each triangle's barycentre (green).
#include "theory/origin/two_triangles.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct Fig27 {
  std::vector<std::string> files;  ///< the names of the files drawn
  double largest_gap = 0;          ///< max over frames and vertices of |v_red − v_green|
};

/// Draws frames t = 0, 1/4, …, 1 of both interpolations side by side, the target triangles A_i(T_i)
/// dashed in the last frame, into the folder `dir`.
Fig27 draw_fig_2_7(const std::filesystem::path& dir, const origin::TwoTriangles& config);

}  // namespace affinterp::plots
