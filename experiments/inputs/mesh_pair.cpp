#include "experiments/inputs/mesh_pair.hpp"

#include "experiments/inputs/mesh_file.hpp"
#include "theory/global/mesh_validation.hpp"

namespace affinterp::io {

MeshPair check_mesh_pair(global::Mesh source, global::Mesh target, const std::string& source_name,
                         const std::string& target_name, const MeshPairOptions& options) {
  using global::InvalidMesh;
  const auto checked = [](const std::string& name, auto&& check) {
    try {
      check();
    } catch (const InvalidMesh& e) {
      throw MeshFileError(name + ": " + e.what());
    }
  };
  checked(source_name, [&] { global::check_well_formed(source); });
  checked(target_name, [&] { global::check_well_formed(target); });
  checked(target_name, [&] { global::check_compatible(source, target); });
  MeshPair pair;
  checked(source_name, [&] { pair.reoriented = global::orient_counter_clockwise(source); });
  if (pair.reoriented) global::reverse_orientation(target);
  pair.flipped_target_triangles = global::flipped_triangles(target);
  if (!pair.flipped_target_triangles.empty() && !options.allow_flipped_target)
    throw MeshFileError(target_name + ": " + std::to_string(pair.flipped_target_triangles.size()) +
                        " target triangle(s) flipped or collapsed relative to the source, first triangle " +
                        std::to_string(pair.flipped_target_triangles.front()) + " (allow with --allow-flipped-target)");
  pair.source = std::move(source);
  pair.target = std::move(target);
  return pair;
}

MeshPair read_mesh_pair(const std::filesystem::path& source, const std::filesystem::path& target,
                        const MeshPairOptions& options) {
  return check_mesh_pair(read_mesh(source), read_mesh(target), source.string(), target.string(), options);
}

}  // namespace affinterp::io
