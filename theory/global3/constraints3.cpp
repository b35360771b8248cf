#include "theory/global3/constraints3.hpp"

namespace affinterp::global3 {

ConstraintTargets3 weighted_targets(const Constraints3& constraints, const std::vector<const Eigen::Matrix3Xd*>& poses,
                                    const Eigen::VectorXd& w) {
  ConstraintTargets3 targets;
  targets.pinned = Eigen::Matrix3Xd::Zero(3, static_cast<Eigen::Index>(constraints.pinned.size()));
  for (std::size_t j = 0; j < poses.size(); ++j) {
    const Eigen::Index k = static_cast<Eigen::Index>(j);
    for (std::size_t p = 0; p < constraints.pinned.size(); ++p)
      targets.pinned.col(static_cast<Eigen::Index>(p)) += w[k] * poses[j]->col(constraints.pinned[p].vertex);
    targets.barycentre += w[k] * poses[j]->rowwise().mean();
  }
  return targets;
}

}  // namespace affinterp::global3
