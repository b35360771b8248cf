#include "theory/global/ldl_subtrees.hpp"

#include "theory/global/parallel_ranges.hpp"

#include <algorithm>

namespace affinterp::global {
namespace {

/// Splits of the tree tried from the root down before settling on the best seen, and the most subtrees packed.
constexpr int most_steps = 4096;
constexpr std::size_t most_subtrees = 64;

}  // namespace

std::optional<LdlSubtrees> split_subtrees(Eigen::Index n, const int* start, const int* row, int skip) {
  const auto size = static_cast<std::size_t>(n);
  // parent, work (1 + entries) and the subtree's work, first column and column count, children first to last
  std::vector<int> parent(size, -1), first(size), count(size, 1);
  std::vector<double> work(size), subtree(size);
  for (std::size_t j = 0; j < size; ++j) {
    const int begin = start[j] + skip, end = start[j + 1];
    if (begin < end) parent[j] = *std::min_element(row + begin, row + end);
    work[j] = 1.0 + (end - begin);
    subtree[j] = work[j];
    first[j] = static_cast<int>(j);
  }
  for (std::size_t j = 0; j < size; ++j)
    if (const int p = parent[j]; p >= 0) {
      if (p <= static_cast<int>(j)) return std::nullopt;  // not a lower triangle's tree
      const auto up = static_cast<std::size_t>(p);
      subtree[up] += subtree[j], count[up] += count[j], first[up] = std::min(first[up], first[j]);
    }
  for (std::size_t j = 0; j < size; ++j)
    if (count[j] != static_cast<int>(j) - first[j] + 1) return std::nullopt;  // not postordered
  std::vector<int> child_start(size + 1, 0), child(size);
  for (std::size_t j = 0; j < size; ++j)
    if (parent[j] >= 0) ++child_start[static_cast<std::size_t>(parent[j]) + 1];
  for (std::size_t j = 0; j < size; ++j) child_start[j + 1] += child_start[j];
  std::vector<int> filled(child_start.begin(), child_start.end() - 1);
  for (std::size_t j = 0; j < size; ++j)
    if (parent[j] >= 0)
      child[static_cast<std::size_t>(filled[static_cast<std::size_t>(parent[j])]++)] = static_cast<int>(j);

  double total = 0;
  for (const double w : work) total += w;
  std::vector<int> subtrees;  // the roots of the candidate subtrees
  for (std::size_t j = 0; j < size; ++j)
    if (parent[j] < 0) subtrees.push_back(static_cast<int>(j));
  double top_work = 0, best = 0.75;
  std::vector<int> best_roots, best_group;
  for (int step = 0; step < most_steps && subtrees.size() <= most_subtrees; ++step) {
    // the heaviest first (the lower column on ties), each to the lighter group (group 0 on ties)
    std::sort(subtrees.begin(), subtrees.end(), [&](int a, int b) {
      const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
      return subtree[ua] != subtree[ub] ? subtree[ua] > subtree[ub] : a < b;
    });
    std::array<double, 2> group_work{0, 0};
    std::vector<int> group;
    for (const int r : subtrees) {
      const int g = group_work[1] < group_work[0] ? 1 : 0;
      group_work[static_cast<std::size_t>(g)] += subtree[static_cast<std::size_t>(r)], group.push_back(g);
    }
    if (const double critical = (std::max(group_work[0], group_work[1]) + top_work) / total; critical < best)
      best = critical, best_roots = subtrees, best_group = group;
    const auto heaviest = static_cast<std::size_t>(subtrees.front());
    if (child_start[heaviest] == child_start[heaviest + 1]) break;
    subtrees.erase(subtrees.begin());
    top_work += work[heaviest];
    for (int c = child_start[heaviest]; c < child_start[heaviest + 1]; ++c)
      subtrees.push_back(child[static_cast<std::size_t>(c)]);
  }
  if (best_roots.empty()) return std::nullopt;

  LdlSubtrees split;
  std::vector<bool> in_subtree(size, false);
  for (std::size_t k = 0; k < best_roots.size(); ++k) {
    const int r = best_roots[k];
    split.ranges[static_cast<std::size_t>(best_group[k])].emplace_back(first[static_cast<std::size_t>(r)], r);
    std::fill(in_subtree.begin() + first[static_cast<std::size_t>(r)], in_subtree.begin() + r + 1, true);
  }
  for (auto& ranges : split.ranges) std::sort(ranges.begin(), ranges.end());
  split.top_index.assign(size, -1);
  for (std::size_t j = 0; j < size; ++j)
    if (!in_subtree[j])
      split.top_index[j] = static_cast<int>(split.top.size()), split.top.push_back(static_cast<int>(j));
  // what the substitution relies on, checked rather than assumed of the structure: a subtree's column has rows
  // in its subtree or the top only, and a top column in the top only
  for (const auto& ranges : split.ranges)
    for (const auto& [first_column, root] : ranges)
      for (int j = first_column; j <= root; ++j)
        for (int s = start[j] + skip; s < start[j + 1]; ++s)
          if (row[s] > root && split.top_index[static_cast<std::size_t>(row[s])] < 0) return std::nullopt;
  for (const int j : split.top)
    for (int s = start[j] + skip; s < start[j + 1]; ++s)
      if (split.top_index[static_cast<std::size_t>(row[s])] < 0) return std::nullopt;
  return split;
}

void for_each_group(std::size_t threads, const std::function<void(std::size_t)>& step) {
  for_each_range(2, threads > 1 ? 2 : 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t g = first; g < last; ++g) step(g);
  });
}

}  // namespace affinterp::global
