#include "theory/global/rotation_branch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <utility>
#include <vector>

namespace affinterp::global {

std::vector<std::vector<Eigen::Index>> dual_graph(const Eigen::Matrix3Xi& triangles) {
  // Sort the (undirected edge, triangle) pairs so that triangles sharing an edge are neighbours.
  std::vector<std::pair<std::pair<int, int>, Eigen::Index>> edges;
  edges.reserve(3 * static_cast<std::size_t>(triangles.cols()));
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)
    for (int c = 0; c < 3; ++c) {
      const int a = triangles(c, i), b = triangles((c + 1) % 3, i);
      edges.push_back({{std::min(a, b), std::max(a, b)}, i});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<Eigen::Index>> adjacent(static_cast<std::size_t>(triangles.cols()));
  for (std::size_t e = 0; e < edges.size();) {
    std::size_t end = e;
    while (end < edges.size() && edges[end].first == edges[e].first) ++end;
    for (std::size_t a = e; a < end; ++a)
      for (std::size_t b = e; b < end; ++b)
        if (a != b) adjacent[static_cast<std::size_t>(edges[a].second)].push_back(edges[b].second);
    e = end;
  }
  return adjacent;
}

Eigen::VectorXd consistent_angles(const Eigen::Matrix3Xi& triangles, const Eigen::VectorXd& principal) {
  const auto adjacent = dual_graph(triangles);
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
      for (const Eigen::Index child : adjacent[static_cast<std::size_t>(parent)]) {
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
