#include "theory/global/rotation_branch.hpp"

#include "theory/global/vertex_stars.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <queue>
#include <utility>
#include <vector>

namespace affinterp::global {

DualGraph dual_graph(const Eigen::Matrix3Xi& triangles) {
  const VertexStars stars = vertex_stars(triangles, triangles.size() > 0 ? triangles.maxCoeff() + 1 : 0);
  DualGraph graph;
  graph.start.reserve(static_cast<std::size_t>(triangles.cols()) + 1);
  graph.start.push_back(0);
  graph.neighbour.reserve(3 * static_cast<std::size_t>(triangles.cols()));
  for (Eigen::Index i = 0; i < triangles.cols(); ++i) {
    std::array<std::pair<int, int>, 3> edges;
    for (int c = 0; c < 3; ++c) {
      const int a = triangles(c, i), b = triangles((c + 1) % 3, i);
      edges[static_cast<std::size_t>(c)] = {std::min(a, b), std::max(a, b)};
    }
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges)  // the other triangles of a's star that hold b, in increasing order
      for (int s = stars.start[static_cast<std::size_t>(a)]; s < stars.start[static_cast<std::size_t>(a) + 1]; ++s) {
        const int j = stars.triangle[static_cast<std::size_t>(s)];
        if (j != i && (triangles.col(j).array() == b).any()) graph.neighbour.push_back(j);
      }
    graph.start.push_back(static_cast<int>(graph.neighbour.size()));
  }
  return graph;
}

Eigen::VectorXd consistent_angles(const Eigen::Matrix3Xi& triangles, const Eigen::VectorXd& principal) {
  const DualGraph graph = dual_graph(triangles);
  Eigen::VectorXd theta = principal;
  std::vector<bool> visited(static_cast<std::size_t>(principal.size()), false);
  constexpr double two_pi = 2 * std::numbers::pi;
  for (Eigen::Index root = 0; root < principal.size(); ++root) {
    if (visited[static_cast<std::size_t>(root)]) continue;
    visited[static_cast<std::size_t>(root)] = true;
    std::queue<Eigen::Index> queue;
    queue.push(root);
    while (!queue.empty()) {
      const Eigen::Index parent = queue.front();
      queue.pop();
      for (int s = graph.start[static_cast<std::size_t>(parent)]; s < graph.start[static_cast<std::size_t>(parent) + 1];
           ++s) {
        const int child = graph.neighbour[static_cast<std::size_t>(s)];
        if (visited[static_cast<std::size_t>(child)]) continue;
        visited[static_cast<std::size_t>(child)] = true;
        theta[child] += two_pi * std::round((theta[parent] - theta[child]) / two_pi);
        queue.push(child);
      }
    }
  }
  return theta;
}

}  // namespace affinterp::global
