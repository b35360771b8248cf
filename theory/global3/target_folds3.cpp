#include "theory/global3/target_folds3.hpp"

#include "theory/global/vertex_stars.hpp"
#include "theory/local3/nearest_rotation3.hpp"

#include <algorithm>

namespace affinterp::global3 {

using Eigen::Index;

namespace {

Eigen::Vector3d normal(const Eigen::Matrix3Xd& v, const Mesh3& mesh, Index i) {
  const Eigen::Vector3d a = v.col(mesh.elements(0, i));
  return (v.col(mesh.elements(1, i)) - a).cross(v.col(mesh.elements(2, i)) - a);
}

}  // namespace

std::vector<Index> target_folds(const Mesh3& source, const Mesh3& target) {
  std::vector<Index> folds;
  if (source.kind() != ElementKind::triangle) return folds;
  const global::VertexStars stars = global::vertex_stars(source.elements, source.vertex_count());
  std::vector<Index> ring;
  for (Index i = 0; i < source.element_count(); ++i) {
    ring.clear();
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::size_t>(source.elements(c, i));
      for (int s = stars.start[k]; s < stars.start[k + 1]; ++s)
        for (int e = 0; e < 3; ++e) ring.push_back(source.elements(e, stars.triangle[static_cast<std::size_t>(s)]));
    }
    std::ranges::sort(ring);
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const Eigen::Matrix3d R =
        local3::fitted_rotation<double>(source.vertices(Eigen::all, ring), target.vertices(Eigen::all, ring));
    if (normal(target.vertices, source, i).dot(R * normal(source.vertices, source, i)) <= 0) folds.push_back(i);
  }
  return folds;
}

std::vector<std::vector<Index>> pose_folds(const std::vector<Mesh3>& poses) {
  std::vector<std::vector<Index>> folds(poses.size());
  for (std::size_t k = 1; k < poses.size(); ++k) folds[k] = target_folds(poses[0], poses[k]);
  return folds;
}

std::vector<unsigned char> near_pose_folds(const std::vector<Mesh3>& poses,
                                           const std::vector<std::vector<Index>>& folds) {
  std::vector<Index> all;
  for (const std::vector<Index>& pose : folds) all.insert(all.end(), pose.begin(), pose.end());
  if (all.empty()) return {};
  return near_folds(poses.front(), all);
}

std::vector<unsigned char> near_folds(const Mesh3& mesh, const std::vector<Index>& folds) {
  std::vector<unsigned char> at_fold_vertex(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (const Index i : folds)
    for (int c = 0; c < mesh.corners(); ++c) at_fold_vertex[static_cast<std::size_t>(mesh.elements(c, i))] = 1;
  std::vector<unsigned char> near(static_cast<std::size_t>(mesh.element_count()), 0);
  for (Index i = 0; i < mesh.element_count(); ++i)
    for (int c = 0; c < mesh.corners(); ++c)
      near[static_cast<std::size_t>(i)] |= at_fold_vertex[static_cast<std::size_t>(mesh.elements(c, i))];
  return near;
}

}  // namespace affinterp::global3
