#include "theory/global3/rotation_branches3.hpp"

#include "theory/local3/rotation_branch3.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>

namespace affinterp::global3 {

DualGraph3 dual_graph3(const Eigen::MatrixXi& elements) {
  const int corners = static_cast<int>(elements.rows());
  // Each facet (the element's vertices but one, sorted; a triangle's third slot −1) with its element; equal
  // facets side by side after sorting are the dual graph's edges.
  std::vector<std::pair<std::array<int, 3>, int>> facets;
  facets.reserve(static_cast<std::size_t>(corners * elements.cols()));
  for (Eigen::Index i = 0; i < elements.cols(); ++i)
    for (int skip = 0; skip < corners; ++skip) {
      std::array<int, 3> facet{-1, -1, -1};
      for (int c = 0, slot = 0; c < corners; ++c)
        if (c != skip) facet[static_cast<std::size_t>(slot++)] = elements(c, i);
      std::sort(facet.begin(), facet.begin() + corners - 1);
      facets.push_back({facet, static_cast<int>(i)});
    }
  std::sort(facets.begin(), facets.end());
  std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(elements.cols()));
  for (std::size_t a = 0; a < facets.size();) {
    std::size_t b = a;
    while (b < facets.size() && facets[b].first == facets[a].first) ++b;
    for (std::size_t x = a; x < b; ++x)
      for (std::size_t y = a; y < b; ++y)
        if (x != y) adjacent[static_cast<std::size_t>(facets[x].second)].push_back(facets[y].second);
    a = b;
  }
  DualGraph3 graph;
  graph.start.push_back(0);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    graph.neighbour.insert(graph.neighbour.end(), list.begin(), list.end());
    graph.start.push_back(static_cast<int>(graph.neighbour.size()));
  }
  return graph;
}

namespace {

/// The walk's state: each element's logarithm, its reference for its children, and the frontier, the unvisited
/// neighbours of visited elements keyed by how far their nearest representative lies from that reference.
struct Walk {
  const DualGraph3& graph;
  const Eigen::Matrix3Xd& principal;
  Eigen::Matrix3Xd omega, reference;
  std::vector<bool> visited;
  using Step = std::tuple<double, int, int>;  ///< (distance, child, parent): smallest first, ties by index
  std::priority_queue<Step, std::vector<Step>, std::greater<Step>> frontier;

  Walk(const DualGraph3& g, const Eigen::Matrix3Xd& p)
      : graph(g), principal(p), omega(p), reference(3, p.cols()), visited(static_cast<std::size_t>(p.cols()), false) {}

  void push_neighbours(int parent) {
    const Eigen::Vector3d r = reference.col(parent);
    for (int s = graph.start[static_cast<std::size_t>(parent)]; s < graph.start[static_cast<std::size_t>(parent) + 1];
         ++s) {
      const int child = graph.neighbour[static_cast<std::size_t>(s)];
      if (!visited[static_cast<std::size_t>(child)])
        frontier.push({(local3::nearest_log<double>(principal.col(child), r) - r).norm(), child, parent});
    }
  }
  /// Visits the element `child` from `parent`: its representative nearest the parent's reference.
  void visit(int child, int parent) {
    visited[static_cast<std::size_t>(child)] = true;
    omega.col(child) = local3::nearest_log<double>(principal.col(child), reference.col(parent));
    const bool reliable = (omega.col(child) - reference.col(parent)).norm() <= reliable_step;
    reference.col(child) = reliable ? omega.col(child) : reference.col(parent);
    push_neighbours(child);
  }
};

}  // namespace

Eigen::Matrix3Xd consistent_logs(const DualGraph3& graph, const Eigen::Matrix3Xd& principal,
                                 const Eigen::Matrix3Xd* root_reference) {
  Walk walk(graph, principal);
  for (Eigen::Index root = 0; root < principal.cols(); ++root) {
    if (walk.visited[static_cast<std::size_t>(root)]) continue;
    walk.visited[static_cast<std::size_t>(root)] = true;
    if (root_reference)
      walk.omega.col(root) = local3::nearest_log<double>(principal.col(root), root_reference->col(root));
    walk.reference.col(root) = walk.omega.col(root);
    walk.push_neighbours(static_cast<int>(root));
    while (!walk.frontier.empty()) {
      const auto [distance, child, parent] = walk.frontier.top();
      walk.frontier.pop();
      if (!walk.visited[static_cast<std::size_t>(child)]) walk.visit(child, parent);
    }
  }
  return walk.omega;
}

}  // namespace affinterp::global3
