#pragma once
// Reading the 3D meshes of the deformation application (thesis Fig. 3.3) from OFF files.
#include "theory/deformation/mesh3.hpp"

#include <filesystem>

namespace affinterp::sym3 {

/// Reads an OFF file (polygons are split into fans of triangles). Throws std::runtime_error naming the
/// file and the problem when it is missing or malformed.
Mesh3 read_off(const std::filesystem::path& file);

}  // namespace affinterp::sym3
