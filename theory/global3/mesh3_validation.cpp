#include "theory/global3/mesh3_validation.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace affinterp::global3 {

using Eigen::Index;
using global::InvalidMesh;

namespace {

std::string element_name(const Mesh3& mesh, Index i) {
  return std::string(mesh.kind() == ElementKind::triangle ? "triangle " : "tetrahedron ") + std::to_string(i);
}

/// The representative of k's set (union–find with path halving).
int find_root(std::vector<int>& parent, int k) {
  while (parent[static_cast<std::size_t>(k)] != k)
    k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}

/// The longest edge's length of element i.
double longest_edge(const Mesh3& mesh, Index i) {
  double longest = 0;
  for (int a = 0; a < mesh.corners(); ++a)
    for (int b = a + 1; b < mesh.corners(); ++b)
      longest = std::max(longest, (mesh.corner(i, b) - mesh.corner(i, a)).norm());
  return longest;
}

}  // namespace

void check_well_formed(const Mesh3& mesh) {
  if (mesh.vertex_count() == 0 || mesh.element_count() == 0)
    throw InvalidMesh("the mesh needs at least one vertex and one element");
  if (mesh.elements.rows() != 3 && mesh.elements.rows() != 4)
    throw InvalidMesh("elements must have 3 (triangles) or 4 (tetrahedra) vertex indices, not " +
                      std::to_string(mesh.elements.rows()));
  for (Index k = 0; k < mesh.vertex_count(); ++k)
    if (!mesh.vertices.col(k).allFinite()) throw InvalidMesh("vertex " + std::to_string(k) + " is not finite");
  for (Index i = 0; i < mesh.element_count(); ++i)
    for (int a = 0; a < mesh.corners(); ++a) {
      const int v = mesh.elements(a, i);
      if (v < 0 || v >= mesh.vertex_count())
        throw InvalidMesh(element_name(mesh, i) + " has vertex index " + std::to_string(v) + " out of range");
      for (int b = 0; b < a; ++b)
        if (mesh.elements(b, i) == v) throw InvalidMesh(element_name(mesh, i) + " repeats vertex " + std::to_string(v));
    }
}

void check_compatible(const Mesh3& reference, const Mesh3& pose) {
  if (pose.vertex_count() != reference.vertex_count())
    throw InvalidMesh("the poses differ in connectivity: " + std::to_string(reference.vertex_count()) + " against " +
                      std::to_string(pose.vertex_count()) + " vertices");
  if (pose.elements.rows() != reference.elements.rows() || pose.element_count() != reference.element_count())
    throw InvalidMesh("the poses differ in connectivity: different element counts or kinds");
  for (Index i = 0; i < reference.element_count(); ++i)
    if (pose.elements.col(i) != reference.elements.col(i))
      throw InvalidMesh("the poses differ in connectivity at " + element_name(reference, i));
}

void check_connected(const Mesh3& mesh) {
  std::vector<int> parent(static_cast<std::size_t>(mesh.vertex_count()));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> used(parent.size(), false);
  for (Index i = 0; i < mesh.element_count(); ++i)
    for (int a = 0; a < mesh.corners(); ++a) {
      used[static_cast<std::size_t>(mesh.elements(a, i))] = true;
      parent[static_cast<std::size_t>(find_root(parent, mesh.elements(a, i)))] = find_root(parent, mesh.elements(0, i));
    }
  for (Index k = 0; k < mesh.vertex_count(); ++k) {
    if (!used[static_cast<std::size_t>(k)]) throw InvalidMesh("vertex " + std::to_string(k) + " is in no element");
    if (find_root(parent, static_cast<int>(k)) != find_root(parent, 0))
      throw InvalidMesh("the mesh is not connected (vertex " + std::to_string(k) +
                        " is in another piece than vertex 0): the minimiser would not be unique");
  }
}

void check_elements(const Mesh3& mesh, const std::string& which) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (Index i = 0; i < mesh.element_count(); ++i) {
    const double h = longest_edge(mesh, i);
    const Eigen::Vector3d e1 = mesh.corner(i, 1) - mesh.corner(i, 0), e2 = mesh.corner(i, 2) - mesh.corner(i, 0);
    if (mesh.kind() == ElementKind::triangle) {
      if (!(e1.cross(e2).norm() > 16 * eps * h * h))
        throw InvalidMesh(which + " " + element_name(mesh, i) + " is degenerate (zero area)");
      continue;
    }
    const double det = e1.cross(e2).dot(mesh.corner(i, 3) - mesh.corner(i, 0));
    if (!(std::abs(det) > 32 * eps * h * h * h))
      throw InvalidMesh(which + " " + element_name(mesh, i) + " is degenerate (zero volume)");
    if (det < 0) throw InvalidMesh(which + " " + element_name(mesh, i) + " is inverted (det <= 0)");
  }
}

void check_reference(const Mesh3& reference, const char* which) {
  check_well_formed(reference);
  check_connected(reference);
  check_elements(reference, which);
}

void check_pose(const Mesh3& reference, const Mesh3& pose, const std::string& which) {
  check_compatible(reference, pose);
  for (Index k = 0; k < pose.vertex_count(); ++k)
    if (!pose.vertices.col(k).allFinite()) throw InvalidMesh(which + " vertex " + std::to_string(k) + " is not finite");
  check_elements(pose, which);
}

}  // namespace affinterp::global3
