#pragma once
// An animated GIF of mesh frames in one common view, drawn in-process (Cairo, plots/mesh_painter.hpp)
// and written by giflib (plots/gif_writer.hpp).
#include "plots/mesh_strip.hpp"

#include <filesystem>

namespace affinterp::plots {

/// Writes `gif` showing `frames` in turn, each labelled, `delay_cs` hundredths of a second each, looping.
/// Throws std::runtime_error (one line) when it cannot be written.
void write_animation_gif(const std::filesystem::path& gif, const Eigen::Matrix3Xi& triangles,
                         const std::vector<MeshFrame>& frames, int delay_cs = 6);

}  // namespace affinterp::plots
