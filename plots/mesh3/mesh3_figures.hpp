#pragma once
// Figures of 3D interpolations and blends (plots/mesh3/mesh3_render.hpp): a filmstrip of frames in time, a
// blend triangle, the poses blended at weights on a triangular grid of the simplex, and one piece of a surface
// in several poses with marked triangles.
#include "plots/mesh3/mesh3_render.hpp"
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <utility>
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

/// One pose of a piece of surface: its vertices and, per triangle, its mark (or none marked: empty).
struct MarkedPatch {
  Eigen::Matrix3Xd vertices;
  std::vector<FaceMark> marks;
  std::string label;  ///< drawn under the patch
};

/// The patches (all of `triangles`) side by side at one scale, each turned onto the first by the rotation that best
/// maps its vertices onto the first's (Kabsch), and the first turned so that its area-weighted normal faces the
/// viewer: the same piece in each pose, seen alike. Under them, a key to the marks in `key`. Returns the file names.
std::vector<std::string> draw_patches3(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                       const std::vector<MarkedPatch>& patches,
                                       const std::vector<std::pair<FaceMark, std::string>>& key,
                                       const std::string& title);

}  // namespace affinterp::plots
