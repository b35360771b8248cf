#pragma once
// Frames of one triangle mesh superimposed in their common coordinates — earlier frames light, later ones
// dark, flipped triangles red — with curves on top (e.g. prescribed vertex loci and the paths the vertices
// actually took), for figures where where things go matters more than each frame's shape.
#include "plots/mesh_strip.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct Curve {
  Eigen::Matrix2Xd points;  ///< a polyline
  std::string label;        ///< in the key; empty: no key entry
  std::string style;        ///< gnuplot style, e.g. "with lines lc rgb '#d08000' lw 2 dt 2"
};

/// Draws `frames` (all with the triangle list `triangles`, in order of time) and `curves` to stem.png and
/// stem.svg; returns the names.
std::vector<std::string> draw_overlay(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                      const std::vector<MeshFrame>& frames, const std::vector<Curve>& curves,
                                      const std::string& title = "");

}  // namespace affinterp::plots
