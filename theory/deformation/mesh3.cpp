#include "theory/deformation/mesh3.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace affinterp::sym3 {

Mesh3 midpoint_subdivision(const Mesh3& mesh) {
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) vertices.push_back(mesh.vertices.col(k));
  std::unordered_map<std::uint64_t, int> midpoint_of_edge;
  auto midpoint = [&](int a, int b) {
    const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    auto [it, inserted] = midpoint_of_edge.try_emplace(key, static_cast<int>(vertices.size()));
    if (inserted) vertices.push_back((mesh.vertices.col(a) + mesh.vertices.col(b)) / 2);
    return it->second;
  };
  Mesh3 fine;
  fine.triangles.resize(3, 4 * mesh.triangle_count());
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i) {
    const int a = mesh.triangles(0, i), b = mesh.triangles(1, i), c = mesh.triangles(2, i);
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    fine.triangles.col(4 * i) << a, ab, ca;
    fine.triangles.col(4 * i + 1) << ab, b, bc;
    fine.triangles.col(4 * i + 2) << ca, bc, c;
    fine.triangles.col(4 * i + 3) << ab, bc, ca;
  }
  fine.vertices.resize(3, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t k = 0; k < vertices.size(); ++k) fine.vertices.col(k) = vertices[k];
  return fine;
}

}  // namespace affinterp::sym3
