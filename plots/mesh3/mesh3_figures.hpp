#pragma once
// Figures of 3D interpolations and blends (plots/mesh3/mesh3_render.hpp): a filmstrip of frames in time and a
// blend triangle, the poses blended at weights on a triangular grid of the simplex.
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct Mesh3Frame {
  Eigen::Matrix3Xd vertices;
  std::string label;  ///< drawn under the frame, e.g. "t = 0.5"
};

/// The frames side by side at one scale (all with `mesh`'s elements), to stem.png and stem.svg; returns the
/// file names.
std::vector<std::string> draw_filmstrip3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                         const std::vector<Mesh3Frame>& frames, const std::string& title);

struct BlendThumbnail {
  Eigen::Vector3d weights;  ///< (w_0, w_1, w_2) on the simplex: where the thumbnail sits in the triangle
  Eigen::Matrix3Xd vertices;
};

/// The thumbnails placed in an equilateral triangle whose corners are poses 0 (top), 1 (bottom left) and 2
/// (bottom right), each at its weights' barycentric position, with the corners' names; returns the file names.
std::vector<std::string> draw_blend_triangle3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                              const std::vector<BlendThumbnail>& thumbnails,
                                              const std::vector<std::string>& pose_names, const std::string& title);

}  // namespace affinterp::plots
