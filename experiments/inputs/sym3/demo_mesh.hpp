#pragma once
// The real mesh of the deformation application: a CGAL demo model from Debian's libcgal-demo package,
// extracted from its data archive at run time.
#include "theory/deformation/mesh3.hpp"

#include <filesystem>
#include <optional>
#include <string_view>

namespace affinterp::sym3 {

/// The data archive of libcgal-demo (OFF meshes under data/meshes/).
inline constexpr std::string_view cgal_demo_archive = "/usr/share/doc/libcgal-dev/data.tar.gz";

/// Extracts data/meshes/`name` from the archive into `folder` (with tar) and reads it; nullopt when the
/// archive is absent. Throws std::runtime_error when extraction or reading fails.
std::optional<Mesh3> cgal_demo_mesh(std::string_view name, const std::filesystem::path& folder);

/// The application's model, standing in for the thesis's dragon (50,000 vertices, 100,000 triangles):
/// ChineseDragon-10kv (10,000 vertices, 19,994 triangles) after one 1→4 midpoint subdivision, i.e.
/// 79,976 triangles on about 40,000 vertices. nullopt when the archive is absent.
std::optional<Mesh3> dragon_mesh(const std::filesystem::path& folder);

}  // namespace affinterp::sym3
