#include "experiments/inputs/shapes/subdivide.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace affinterp::shapes {

MeshPairShapes subdivided(const MeshPairShapes& pair) {
  const global::Mesh &P = pair.source, &Q = pair.target;
  const Eigen::Index n = P.vertex_count(), m = P.triangle_count();
  std::unordered_map<std::uint64_t, int> midpoint;  // edge {a < b} → its midpoint's index
  midpoint.reserve(static_cast<std::size_t>(2 * m));
  std::vector<std::pair<int, int>> edges;
  auto middle = [&](int a, int b) {
    const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    const auto [slot, added] = midpoint.try_emplace(key, static_cast<int>(n + static_cast<Eigen::Index>(edges.size())));
    if (added) edges.emplace_back(a, b);
    return slot->second;
  };
  Eigen::Matrix3Xi triangles(3, 4 * m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const int a = P.triangles(0, i), b = P.triangles(1, i), c = P.triangles(2, i);
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    triangles.col(4 * i) << a, ab, ca;
    triangles.col(4 * i + 1) << ab, b, bc;
    triangles.col(4 * i + 2) << ca, bc, c;
    triangles.col(4 * i + 3) << ab, bc, ca;
  }
  MeshPairShapes fine{{Eigen::Matrix2Xd(2, n + static_cast<Eigen::Index>(edges.size())), triangles},
                      {Eigen::Matrix2Xd(2, n + static_cast<Eigen::Index>(edges.size())), triangles}};
  fine.source.vertices.leftCols(n) = P.vertices;
  fine.target.vertices.leftCols(n) = Q.vertices;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    const Eigen::Index k = n + static_cast<Eigen::Index>(e);
    fine.source.vertices.col(k) = (P.vertices.col(a) + P.vertices.col(b)) / 2;
    fine.target.vertices.col(k) = (Q.vertices.col(a) + Q.vertices.col(b)) / 2;
  }
  return fine;
}

}  // namespace affinterp::shapes
