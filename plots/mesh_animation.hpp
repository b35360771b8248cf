#pragma once
// An animated GIF of mesh frames: each frame drawn by gnuplot (pngcairo) in one common view, then joined
// by ImageMagick's `convert`.
#include "plots/mesh_strip.hpp"

#include <filesystem>
#include <optional>

namespace affinterp::plots {

/// The path of ImageMagick's `convert` on PATH, if any.
std::optional<std::filesystem::path> find_convert();

/// Writes `gif` showing `frames` in turn (`delay_cs` hundredths of a second each, looping). Returns false
/// and writes nothing when `convert` is not found; throws std::runtime_error when drawing fails.
bool write_animation_gif(const std::filesystem::path& gif, const Eigen::Matrix3Xi& triangles,
                         const std::vector<MeshFrame>& frames, int delay_cs = 6);

}  // namespace affinterp::plots
