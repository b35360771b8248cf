#pragma once
// A source and a target mesh read from files and checked to be a valid input of Kaji §2: well formed,
// the same triangle list, source triangles non-degenerate and oriented alike (reoriented
// counter-clockwise when all run clockwise), target triangles not flipped unless allowed.
#include "theory/global/mesh.hpp"

#include <filesystem>
#include <vector>

namespace affinterp::io {

struct MeshPair {
  global::Mesh source, target;                         ///< one triangle list, source counter-clockwise
  bool reoriented = false;                             ///< the files' triangles ran clockwise and were reversed
  std::vector<Eigen::Index> flipped_target_triangles;  ///< det A_i ≤ 0 (only when allowed)
};

struct MeshPairOptions {
  bool allow_flipped_target = false;  ///< accept target triangles with det A_i ≤ 0 (reported)
};

/// Reads and checks the pair; throws MeshFileError with one line naming the file and the element.
MeshPair read_mesh_pair(const std::filesystem::path& source, const std::filesystem::path& target,
                        const MeshPairOptions& options = {});

/// The same checks on meshes already in memory; `source_name`/`target_name` prefix the messages.
MeshPair check_mesh_pair(global::Mesh source, global::Mesh target, const std::string& source_name,
                         const std::string& target_name, const MeshPairOptions& options = {});

}  // namespace affinterp::io
