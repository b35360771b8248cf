#pragma once
// Generated 3D shapes with known in-between poses: a bar of tetrahedra and an open tube of triangles along the
// x axis, twists about that axis (the bar twisted by θ has, at time t of a twist, the exact pose twisted by tθ)
// and a bend. The inputs of the 3D claims and figures, and of the tests of theory/global3.
#include "theory/global3/mesh3.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace affinterp::shapes3d {

using global3::Mesh3;

/// The bar [0, length] × [−w/2, w/2]² cut into `slices` boxes along x, each box into 6 tetrahedra by Kuhn's
/// triangulation (conforming across boxes), positively oriented. Vertex 4s + 2j + k is at
/// (s·length/slices, (j − ½)w, (k − ½)w).
inline Mesh3 tetrahedral_bar(int slices, double length, double width = 1) {
  Mesh3 bar;
  bar.vertices.resize(3, 4 * (slices + 1));
  for (int s = 0; s <= slices; ++s)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        bar.vertices.col(4 * s + 2 * j + k) << s * length / slices, (j - 0.5) * width, (k - 0.5) * width;
  bar.elements.resize(4, 6 * slices);
  const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  int e = 0;
  for (int s = 0; s < slices; ++s)
    for (const auto& order : orders) {
      std::array<int, 3> step{0, 0, 0};  // (box step along x, j, k): the Kuhn path from corner 0 to corner 7
      std::array<int, 4> corners{};
      for (int c = 0; c < 4; ++c) {
        corners[static_cast<std::size_t>(c)] = 4 * (s + step[0]) + 2 * step[1] + step[2];
        if (c < 3) step[static_cast<std::size_t>(order[static_cast<std::size_t>(c)])] = 1;
      }
      bar.elements.col(e++) << corners[0], corners[1], corners[2], corners[3];
    }
  for (int i = 0; i < bar.elements.cols(); ++i) {  // orient: det [p1−p0 p2−p0 p3−p0] > 0
    Eigen::Matrix3d E;
    for (int c = 1; c < 4; ++c) E.col(c - 1) = bar.corner(i, c) - bar.corner(i, 0);
    if (E.determinant() < 0) std::swap(bar.elements(1, i), bar.elements(2, i));
  }
  return bar;
}

/// The open tube of radius 1 around the x axis on [0, length]: `rings` + 1 rings of `around` vertices, each
/// quad between rings split into two triangles (outward normals).
inline Mesh3 triangle_tube(int rings, int around, double length) {
  Mesh3 tube;
  tube.vertices.resize(3, (rings + 1) * around);
  for (int r = 0; r <= rings; ++r)
    for (int a = 0; a < around; ++a) {
      const double phi = 2 * std::numbers::pi * a / around;
      tube.vertices.col(r * around + a) << r * length / rings, std::cos(phi), std::sin(phi);
    }
  tube.elements.resize(3, 2 * rings * around);
  int e = 0;
  for (int r = 0; r < rings; ++r)
    for (int a = 0; a < around; ++a) {
      const int p = r * around + a, q = r * around + (a + 1) % around;
      tube.elements.col(e++) << p, p + around, q;
      tube.elements.col(e++) << q, p + around, q + around;
    }
  return tube;
}

/// Each vertex turned about the x axis by turn · x / length.
inline Mesh3 twisted(Mesh3 mesh, double turn, double length) {
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const double phi = turn * mesh.vertices(0, k) / length, y = mesh.vertices(1, k), z = mesh.vertices(2, k);
    mesh.vertices(1, k) = std::cos(phi) * y - std::sin(phi) * z;
    mesh.vertices(2, k) = std::sin(phi) * y + std::cos(phi) * z;
  }
  return mesh;
}

/// A smooth, non-rigid deformation: the bar or tube bent in the xy-plane, stretched along z, shifted.
inline Mesh3 bent(Mesh3 mesh, double length) {
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const Eigen::Vector3d p = mesh.vertices.col(k);
    const double phi = 1.2 * p.x() / length, radius = length / 1.2 + p.y();
    mesh.vertices.col(k) << radius * std::sin(phi) + 0.3, radius * std::cos(phi) - length / 1.2, 1.3 * p.z() - 0.2;
  }
  return mesh;
}

}  // namespace affinterp::shapes3d
