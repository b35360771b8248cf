#include "experiments/inputs/mesh3_poses.hpp"

#include "experiments/inputs/mesh3_file.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "theory/global3/mesh3_validation.hpp"

#include <Eigen/Dense>

namespace affinterp::io {

namespace {

using global3::Mesh3;

const char* element_kind_name(const Mesh3& mesh) { return mesh.corners() == 4 ? "tetrahedra" : "triangles"; }

/// Whether every tetrahedron has det [p1−p0 p2−p0 p3−p0] < 0 (a consistently reversed orientation).
bool all_tetrahedra_reversed(const Mesh3& mesh) {
  if (mesh.corners() != 4) return false;
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i) {
    Eigen::Matrix3d edges;
    for (int c = 1; c < 4; ++c) edges.col(c - 1) = mesh.corner(i, c) - mesh.corner(i, 0);
    if (!(edges.determinant() < 0)) return false;
  }
  return true;
}

}  // namespace

void check_poses3(const std::vector<Mesh3>& poses, const std::vector<std::string>& names) {
  for (std::size_t k = 1; k < poses.size(); ++k)
    if (poses[k].corners() != poses[0].corners())
      throw MeshFileError(names[k] + ": " + element_kind_name(poses[k]) + " where " + names[0] + " has " +
                          element_kind_name(poses[0]) + " (mixed triangles and tetrahedra)");
  std::size_t k = 0;
  try {
    global3::check_reference(poses[0], "mesh");
    for (k = 1; k < poses.size(); ++k) global3::check_pose(poses[0], poses[k], "mesh");
  } catch (const global::RefusedProblem& e) {
    throw MeshFileError(names[k] + ": " + e.what());
  }
}

Poses3 read_poses3(const std::vector<std::filesystem::path>& files) {
  return read_poses3(std::vector<std::optional<Mesh3>>(files.size()), files);
}

Poses3 read_poses3(std::vector<std::optional<Mesh3>> meshes, const std::vector<std::filesystem::path>& files) {
  Poses3 read;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < files.size(); ++k) {
    read.poses.push_back(k < meshes.size() && meshes[k] ? std::move(*meshes[k]) : read_mesh3(files[k]));
    names.push_back(files[k].string());
  }
  if (read.poses.empty()) throw MeshFileError("no mesh given");
  read.reoriented = all_tetrahedra_reversed(read.poses[0]);
  if (read.reoriented)
    for (Mesh3& pose : read.poses)
      if (pose.corners() == 4) pose.elements.row(1).swap(pose.elements.row(2));
  check_poses3(read.poses, names);
  return read;
}

}  // namespace affinterp::io
