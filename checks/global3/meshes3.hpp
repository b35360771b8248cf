#pragma once
// The tests' 3D meshes: the generated bar, tube, twists and bend (experiments/inputs/shapes3d/bar3.hpp, shared
// with the claims and figures), a bounding-box size and a reader for the cat poses' OFF files.
#include "experiments/inputs/shapes3d/bar3.hpp"
#include "theory/global3/mesh3.hpp"

#include <Eigen/Dense>

#include <fstream>
#include <optional>
#include <string>

namespace meshes3 {

using affinterp::global3::Mesh3;

using affinterp::shapes3d::bent;
using affinterp::shapes3d::tetrahedral_bar;
using affinterp::shapes3d::triangle_tube;
using affinterp::shapes3d::twisted;

/// The length of the bounding box's diagonal.
inline double box_diagonal(const Eigen::Matrix3Xd& v) {
  return (v.rowwise().maxCoeff() - v.rowwise().minCoeff()).norm();
}

/// An OFF triangle mesh (the cat poses' format: header, counts, vertices, "3 a b c" faces), or nothing.
inline std::optional<Mesh3> read_off(const std::string& path) {
  std::ifstream in(path);
  std::string header;
  long n = 0, m = 0, edges = 0;
  if (!(in >> header >> n >> m >> edges) || header != "OFF") return std::nullopt;
  Mesh3 mesh;
  mesh.vertices.resize(3, n);
  mesh.elements.resize(3, m);
  for (long k = 0; k < n; ++k) in >> mesh.vertices(0, k) >> mesh.vertices(1, k) >> mesh.vertices(2, k);
  for (long i = 0; i < m; ++i) {
    int corners = 0;
    in >> corners >> mesh.elements(0, i) >> mesh.elements(1, i) >> mesh.elements(2, i);
    if (corners != 3) return std::nullopt;
  }
  return in ? std::optional<Mesh3>(mesh) : std::nullopt;
}

}  // namespace meshes3
