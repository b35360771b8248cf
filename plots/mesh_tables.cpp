#include "plots/mesh_tables.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace affinterp::plots {

namespace {

/// Each edge once as (smaller, larger) vertex index; with `boundary_only`, only edges of one triangle.
std::vector<std::pair<int, int>> edge_list(const Eigen::Matrix3Xi& triangles, bool boundary_only) {
  std::vector<std::pair<int, int>> all;
  all.reserve(static_cast<std::size_t>(3 * triangles.cols()));
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)
    for (int c = 0; c < 3; ++c) {
      const int a = triangles(c, i), b = triangles((c + 1) % 3, i);
      all.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(all.begin(), all.end());
  std::vector<std::pair<int, int>> edges;
  for (std::size_t j = 0; j < all.size();) {
    std::size_t k = j;
    while (k < all.size() && all[k] == all[j]) ++k;
    if (!boundary_only || k - j == 1) edges.push_back(all[j]);
    j = k;
  }
  return edges;
}

}  // namespace

void append(Table& table, const Table& more) { table.insert(table.end(), more.begin(), more.end()); }

MeshTables mesh_tables(const Eigen::Matrix3Xi& triangles, const Eigen::Matrix2Xd& vertices,
                       const Eigen::Vector2d& offset) {
  const bool detailed = triangles.cols() <= detailed_triangle_limit;
  const auto point = [&](int k) { return Row{vertices(0, k) + offset.x(), vertices(1, k) + offset.y()}; };
  MeshTables tables;
  for (const auto& [a, b] : edge_list(triangles, !detailed)) {
    tables.edges.push_back(point(a));
    tables.edges.push_back(point(b));
    tables.edges.push_back({});
  }
  for (Eigen::Index i = 0; i < triangles.cols(); ++i) {
    const Eigen::Vector2d p0 = vertices.col(triangles(0, i)), p1 = vertices.col(triangles(1, i)),
                          p2 = vertices.col(triangles(2, i));
    const Eigen::Vector2d e1 = p1 - p0, e2 = p2 - p0;
    const bool flipped = e1.x() * e2.y() - e1.y() * e2.x() <= 0;
    if (!flipped && !detailed) continue;
    Table& polygons = flipped ? tables.flipped : tables.triangles;
    for (int c : {0, 1, 2, 0}) polygons.push_back(point(triangles(c, i)));
    polygons.push_back({});
    polygons.push_back({});
  }
  return tables;
}

}  // namespace affinterp::plots
