#pragma once
// Compatible 3D poses from files (a source and a target, or the poses of a blend): one connectivity, each mesh
// valid input of the 3D engine (theory/global3/mesh3_validation.hpp's rules: finite coordinates, no degenerate
// or inverted element, a connected reference). A refusal is one MeshFileError line naming the file.
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace affinterp::io {

struct Poses3 {
  std::vector<global3::Mesh3> poses;  ///< in the files' order, one element list
  /// Every tetrahedron of the first file was negatively oriented: corners 1 and 2 were swapped in all poses
  /// (the same solids; MEDIT files from other meshers use either orientation).
  bool reoriented = false;
};

/// Reads and checks `files` (at least one; read_mesh3's formats); throws MeshFileError.
Poses3 read_poses3(const std::vector<std::filesystem::path>& files);
/// The same for meshes already read from `files` (nullopt: read it here), so that no file is read twice.
Poses3 read_poses3(std::vector<std::optional<global3::Mesh3>> read, const std::vector<std::filesystem::path>& files);

/// Checks meshes already in memory as read_poses3 does, `names` naming them in messages; throws MeshFileError.
void check_poses3(const std::vector<global3::Mesh3>& poses, const std::vector<std::string>& names);

}  // namespace affinterp::io
