#include "theory/global/mesh_validation.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace affinterp::global {

namespace {

std::string str(Eigen::Index i) { return std::to_string(i); }

}  // namespace

void check_well_formed(const Mesh& mesh) {
  if (mesh.vertex_count() == 0) throw InvalidMesh("the mesh has no vertices");
  if (mesh.triangle_count() == 0) throw InvalidMesh("the mesh has no triangles");
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k)
    if (!mesh.vertices.col(k).allFinite()) throw InvalidMesh("vertex " + str(k) + " has a non-finite coordinate");
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const int k = mesh.triangles(c, i);
      if (k < 0 || k >= mesh.vertex_count())
        throw InvalidMesh("triangle " + str(i) + " refers to vertex " + std::to_string(k) + " of " +
                          str(mesh.vertex_count()));
    }
    const auto& t = mesh.triangles.col(i);
    if (t(0) == t(1) || t(1) == t(2) || t(0) == t(2)) throw InvalidMesh("triangle " + str(i) + " uses a vertex twice");
  }
}

void check_compatible(const Mesh& source, const Mesh& target) {
  if (source.vertex_count() != target.vertex_count())
    throw InvalidMesh("the target has " + str(target.vertex_count()) + " vertices, the source " +
                      str(source.vertex_count()));
  if (source.triangle_count() != target.triangle_count())
    throw InvalidMesh("the target has " + str(target.triangle_count()) + " triangles, the source " +
                      str(source.triangle_count()));
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i)
    if (source.triangles.col(i) != target.triangles.col(i))
      throw InvalidMesh("triangle " + str(i) + " differs between source and target: the face lists must match");
}

void check_connected(const Mesh& mesh) {
  const auto n = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<std::size_t> parent(n);  // union-find over the vertices, joined by each triangle
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::vector<bool> used(n, false);
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::size_t>(mesh.triangles(c, i));
      used[k] = true;
      parent[root(k)] = root(static_cast<std::size_t>(mesh.triangles(0, i)));
    }
  for (std::size_t k = 0; k < n; ++k) {
    if (!used[k])
      throw InvalidMesh("vertex " + std::to_string(k) + " belongs to no triangle, so nothing determines its path");
    if (root(k) != root(0))
      throw InvalidMesh("the mesh is in more than one connected piece; each piece would need its own constraints");
  }
}

void check_orientation_preserved(const Mesh& source, const Mesh& target) {
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) {
    const double ps = source.doubled_signed_area(i), qs = target.doubled_signed_area(i);
    if (ps == 0) throw InvalidMesh("source triangle " + str(i) + " is degenerate (zero area)");
    if (qs == 0 || (ps > 0) != (qs > 0))  // det A_i = qs / ps (eq. (1))
      throw InvalidMesh("target triangle " + str(i) +
                        " is degenerate or flipped relative to the source (det A_i <= 0, so A_i is not in GL+(2))");
  }
}

bool is_degenerate(const Mesh& mesh, Eigen::Index i) {
  double longest = 0;
  for (int c = 0; c < 3; ++c)
    longest = std::max(longest, (mesh.corner(i, (c + 1) % 3) - mesh.corner(i, c)).squaredNorm());
  return std::abs(mesh.doubled_signed_area(i)) <= 8 * std::numeric_limits<double>::epsilon() * longest;
}

bool orient_counter_clockwise(Mesh& source) {
  Eigen::Index first_ccw = -1, first_cw = -1;
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) {
    if (is_degenerate(source, i)) throw InvalidMesh("source triangle " + str(i) + " has zero area");
    Eigen::Index& first = source.doubled_signed_area(i) > 0 ? first_ccw : first_cw;
    if (first < 0) first = i;
  }
  if (first_ccw >= 0 && first_cw >= 0)
    throw InvalidMesh("source triangles " + str(first_ccw) + " (counter-clockwise) and " + str(first_cw) +
                      " (clockwise) have opposite orientations: the source folds over itself");
  if (first_cw < 0) return false;
  reverse_orientation(source);
  return true;
}

void reverse_orientation(Mesh& mesh) { mesh.triangles.row(1).swap(mesh.triangles.row(2)); }

std::vector<Eigen::Index> flipped_triangles(const Mesh& target) {
  std::vector<Eigen::Index> flipped;
  for (Eigen::Index i = 0; i < target.triangle_count(); ++i)
    if (target.doubled_signed_area(i) <= 0 || is_degenerate(target, i)) flipped.push_back(i);
  return flipped;
}

}  // namespace affinterp::global
