#pragma once
// A filmstrip: frames of one triangle mesh side by side at a common scale, each labelled (e.g. "t = 0.5"),
// filled light to dark in time, flipped triangles red. Drawn in-process (plots/mesh_painter.hpp).
#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct MeshFrame {
  Eigen::Matrix2Xd vertices;
  std::string label;
};

/// Draws `frames` (in order of time, all with the triangle list `triangles`, counter-clockwise in the
/// source) to stem.png and stem.svg; returns the file names.
std::vector<std::string> draw_filmstrip(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                        const std::vector<MeshFrame>& frames, const std::string& title = "");

}  // namespace affinterp::plots
