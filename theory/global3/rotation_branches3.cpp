#include "theory/global3/rotation_branches3.hpp"

#include "theory/local3/rotation3.hpp"
#include "theory/local3/rotation_branch3.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <numbers>
#include <queue>
#include <tuple>
#include <utility>

namespace affinterp::global3 {

Eigen::Vector3d relative_turn(const Eigen::Vector3d& omega_i, const Eigen::Vector3d& omega_j) {
  return local3::rotation_log<double>(local3::rotation_exp_product<double>(omega_j, Eigen::Vector3d(-omega_i)));
}

DualGraph3 dual_graph3(const Eigen::MatrixXi& elements) {
  const int corners = static_cast<int>(elements.rows());
  const auto m = static_cast<std::size_t>(elements.cols());
  // Each facet (the element's vertices but one, sorted; a triangle's third slot −1) with its element, bucketed by
  // its smallest vertex (a counting sort: linear in the facets); equal facets in one bucket are the dual graph's
  // edges. A bucket holds the few facets around one vertex, compared pairwise.
  struct Facet {
    std::array<int, 3> vertices;
    int element;
  };
  std::vector<Facet> facets;
  facets.reserve(m * static_cast<std::size_t>(corners));
  int vertex_count = 0;
  for (Eigen::Index i = 0; i < elements.cols(); ++i)
    for (int skip = 0; skip < corners; ++skip) {
      std::array<int, 3> facet{-1, -1, -1};
      for (int c = 0, slot = 0; c < corners; ++c)
        if (c != skip) facet[static_cast<std::size_t>(slot++)] = elements(c, i);
      std::sort(facet.begin(), facet.begin() + corners - 1);
      vertex_count = std::max(vertex_count, facet[static_cast<std::size_t>(corners - 2)] + 1);
      facets.push_back({facet, static_cast<int>(i)});
    }
  std::vector<int> bucket_start(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (const Facet& f : facets) ++bucket_start[static_cast<std::size_t>(f.vertices[0]) + 1];
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertex_count); ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<int> next(bucket_start.begin(), bucket_start.end() - 1), order(facets.size());
  for (std::size_t k = 0; k < facets.size(); ++k)
    order[static_cast<std::size_t>(next[static_cast<std::size_t>(facets[k].vertices[0])]++)] = static_cast<int>(k);
  // Each pair (element, neighbour) both ways, then grouped by element by a second counting sort.
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(facets.size());
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertex_count); ++v)
    for (int a = bucket_start[v]; a < bucket_start[v + 1]; ++a)
      for (int b = a + 1; b < bucket_start[v + 1]; ++b) {
        const Facet &x = facets[static_cast<std::size_t>(order[static_cast<std::size_t>(a)])],
                    &y = facets[static_cast<std::size_t>(order[static_cast<std::size_t>(b)])];
        if (x.vertices == y.vertices && x.element != y.element) {
          pairs.emplace_back(x.element, y.element);
          pairs.emplace_back(y.element, x.element);
        }
      }
  DualGraph3 graph;
  graph.start.assign(m + 1, 0);
  for (const auto& [i, j] : pairs) ++graph.start[static_cast<std::size_t>(i) + 1];
  for (std::size_t i = 0; i < m; ++i) graph.start[i + 1] += graph.start[i];
  graph.neighbour.resize(pairs.size());
  std::vector<int> fill(graph.start.begin(), graph.start.end() - 1);
  for (const auto& [i, j] : pairs) graph.neighbour[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = j;
  // Each element's neighbours in increasing order, once each (two elements may share several facets).
  std::vector<int> compact_start(m + 1, 0);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const auto first = graph.neighbour.begin() + graph.start[i], last = graph.neighbour.begin() + graph.start[i + 1];
    std::sort(first, last);
    const auto unique_end = std::unique(first, last);
    compact_start[i] = static_cast<int>(kept);
    for (auto it = first; it != unique_end; ++it) graph.neighbour[kept++] = *it;
  }
  compact_start[m] = static_cast<int>(kept);
  graph.neighbour.resize(kept);
  graph.start = std::move(compact_start);
  return graph;
}

namespace {

constexpr double pi = std::numbers::pi;

/// The walk's state: each element's logarithm, its reference for its children, and the frontier, the unvisited
/// neighbours of visited elements keyed by how far their nearest representative lies from that reference.
struct Walk {
  const DualGraph3& graph;
  const Eigen::Matrix3Xd& principal;
  Eigen::Matrix3Xd omega, reference, seed;
  std::vector<bool> visited;
  using Step = std::tuple<double, int, int>;  ///< (distance, child, parent): smallest first, ties by index
  std::priority_queue<Step, std::vector<Step>, std::greater<Step>> frontier;

  Walk(const DualGraph3& g, const Eigen::Matrix3Xd& p)
      : graph(g),
        principal(p),
        omega(p),
        reference(3, p.cols()),
        seed(3, p.cols()),
        visited(static_cast<std::size_t>(p.cols()), false) {}

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
    Eigen::Vector3d predicted = reference.col(parent);
    omega.col(child) = local3::nearest_log<double>(principal.col(child), predicted);
    double step = (omega.col(child) - predicted).norm();
    if (step > reliable_step) {  // the parent's reference advanced by the child's turn relative to the parent
      const Eigen::Vector3d turn = relative_turn(principal.col(parent), principal.col(child));
      if (turn.norm() <= reliable_step) {
        predicted += turn;
        omega.col(child) = local3::nearest_log<double>(principal.col(child), predicted);
        step = (omega.col(child) - predicted).norm();
      }
    }
    reference.col(child) = step <= reliable_step ? omega.col(child) : predicted;
    seed.col(child) = step <= pi ? omega.col(child) : predicted;
    push_neighbours(child);
  }
};

}  // namespace

ConsistentLogs consistent_logs(const DualGraph3& graph, const Eigen::Matrix3Xd& principal,
                               const Eigen::Matrix3Xd* root_reference) {
  Walk walk(graph, principal);
  for (Eigen::Index root = 0; root < principal.cols(); ++root) {
    if (walk.visited[static_cast<std::size_t>(root)]) continue;
    walk.visited[static_cast<std::size_t>(root)] = true;
    if (root_reference)
      walk.omega.col(root) = local3::nearest_log<double>(principal.col(root), root_reference->col(root));
    walk.reference.col(root) = walk.seed.col(root) = walk.omega.col(root);
    walk.push_neighbours(static_cast<int>(root));
    while (!walk.frontier.empty()) {
      const auto [distance, child, parent] = walk.frontier.top();
      walk.frontier.pop();
      if (!walk.visited[static_cast<std::size_t>(child)]) walk.visit(child, parent);
    }
  }
  return {std::move(walk.omega), std::move(walk.seed)};
}

}  // namespace affinterp::global3
