#include "theory/global3/constraints3.hpp"

#include "theory/global/locus.hpp"

#include <stdexcept>

namespace affinterp::global3 {

std::vector<global::PinnedVertex> vertex_terms(const Constraints3& constraints) {
  std::vector<global::PinnedVertex> terms = constraints.pinned;
  for (const VertexLocus3& locus : constraints.loci) terms.push_back({locus.vertex, locus.weight});
  return terms;
}

ConstraintTargets3 interpolation_targets(const Constraints3& constraints, const Eigen::Matrix3Xd& source,
                                         const Eigen::Matrix3Xd& target, double t) {
  ConstraintTargets3 targets;
  targets.vertices.resize(3, static_cast<Eigen::Index>(constraints.pinned.size() + constraints.loci.size()));
  Eigen::Index j = 0;
  for (const global::PinnedVertex& pin : constraints.pinned)
    targets.vertices.col(j++) = (1 - t) * source.col(pin.vertex) + t * target.col(pin.vertex);
  for (const VertexLocus3& locus : constraints.loci) targets.vertices.col(j++) = global::Locus3(locus.points).at(t);
  if (constraints.barycentre && constraints.barycentre->points.cols() > 0)
    targets.barycentre = global::Locus3(constraints.barycentre->points).at(t);
  else
    targets.barycentre = (1 - t) * source.rowwise().mean() + t * target.rowwise().mean();
  return targets;
}

ConstraintTargets3 weighted_targets(const Constraints3& constraints, const std::vector<const Eigen::Matrix3Xd*>& poses,
                                    const Eigen::VectorXd& w) {
  if (!constraints.loci.empty() || (constraints.barycentre && constraints.barycentre->points.cols() > 0))
    throw std::invalid_argument("a blend's constraints are pins and the barycentre's weighted sum: loci have no time");
  ConstraintTargets3 targets;
  targets.vertices = Eigen::Matrix3Xd::Zero(3, static_cast<Eigen::Index>(constraints.pinned.size()));
  for (std::size_t j = 0; j < poses.size(); ++j) {
    const Eigen::Index k = static_cast<Eigen::Index>(j);
    for (std::size_t p = 0; p < constraints.pinned.size(); ++p)
      targets.vertices.col(static_cast<Eigen::Index>(p)) += w[k] * poses[j]->col(constraints.pinned[p].vertex);
    targets.barycentre += w[k] * poses[j]->rowwise().mean();
  }
  return targets;
}

}  // namespace affinterp::global3
