#pragma once
// A filmstrip: frames of one triangle mesh side by side at a common scale, each labelled (e.g. "t = 0.5"),
// flipped triangles filled red.
#include "plots/figure.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct MeshFrame {
  Eigen::Matrix2Xd vertices;
  std::string label;
};

/// Draws `frames` (all with the triangle list `triangles`) to stem.png and stem.svg; returns the names.
std::vector<std::string> draw_filmstrip(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                        const std::vector<MeshFrame>& frames, const std::string& title = "");

/// The gnuplot commands that draw a mesh from the datablocks $triangles, $flipped and $edges.
std::string mesh_plot_command(bool has_triangles, bool has_flipped);

}  // namespace affinterp::plots
