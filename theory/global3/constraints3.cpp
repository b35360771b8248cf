#include "theory/global3/constraints3.hpp"

#include <stdexcept>

namespace affinterp::global3 {

std::vector<global::PinnedVertex> vertex_terms(const Constraints3& constraints) {
  std::vector<global::PinnedVertex> terms = constraints.pinned;
  for (const VertexLocus3& locus : constraints.loci) terms.push_back({locus.vertex, locus.weight});
  return terms;
}

InterpolationTargets3::InterpolationTargets3(const Constraints3& constraints, const Eigen::Matrix3Xd& source,
                                             const Eigen::Matrix3Xd& target)
    : pinned_source_(3, static_cast<Eigen::Index>(constraints.pinned.size())),
      pinned_target_(3, pinned_source_.cols()),
      barycentre_source_(source.rowwise().mean()),
      barycentre_target_(target.rowwise().mean()) {
  for (std::size_t j = 0; j < constraints.pinned.size(); ++j) {
    pinned_source_.col(static_cast<Eigen::Index>(j)) = source.col(constraints.pinned[j].vertex);
    pinned_target_.col(static_cast<Eigen::Index>(j)) = target.col(constraints.pinned[j].vertex);
  }
  for (const VertexLocus3& locus : constraints.loci) loci_.emplace_back(locus.points);
  if (constraints.barycentre && constraints.barycentre->points.cols() > 0)
    barycentre_locus_.emplace(constraints.barycentre->points);
}

ConstraintTargets3 InterpolationTargets3::at(double t) const {
  ConstraintTargets3 targets;
  targets.vertices.resize(3, pinned_source_.cols() + static_cast<Eigen::Index>(loci_.size()));
  targets.vertices.leftCols(pinned_source_.cols()) = (1 - t) * pinned_source_ + t * pinned_target_;
  for (std::size_t l = 0; l < loci_.size(); ++l)
    targets.vertices.col(pinned_source_.cols() + static_cast<Eigen::Index>(l)) = loci_[l].at(t);
  targets.barycentre = barycentre_locus_ ? barycentre_locus_->at(t)
                                         : Eigen::Vector3d((1 - t) * barycentre_source_ + t * barycentre_target_);
  return targets;
}

BlendTargets3::BlendTargets3(const Constraints3& constraints, const std::vector<Mesh3>& poses)
    : barycentres_(3, static_cast<Eigen::Index>(poses.size())) {
  if (!constraints.loci.empty() || (constraints.barycentre && constraints.barycentre->points.cols() > 0))
    throw std::invalid_argument("a blend's constraints are pins and the barycentre's weighted sum: loci have no time");
  for (std::size_t j = 0; j < poses.size(); ++j) {
    Eigen::Matrix3Xd& pinned = pinned_.emplace_back(3, static_cast<Eigen::Index>(constraints.pinned.size()));
    for (std::size_t p = 0; p < constraints.pinned.size(); ++p)
      pinned.col(static_cast<Eigen::Index>(p)) = poses[j].vertices.col(constraints.pinned[p].vertex);
    barycentres_.col(static_cast<Eigen::Index>(j)) = poses[j].vertices.rowwise().mean();
  }
}

ConstraintTargets3 BlendTargets3::at(const Eigen::VectorXd& w) const {
  ConstraintTargets3 targets;
  targets.vertices = Eigen::Matrix3Xd::Zero(3, pinned_.front().cols());
  for (std::size_t j = 0; j < pinned_.size(); ++j) {
    const Eigen::Index k = static_cast<Eigen::Index>(j);
    targets.vertices += w[k] * pinned_[j];
    targets.barycentre += w[k] * barycentres_.col(k);
  }
  return targets;
}

}  // namespace affinterp::global3
