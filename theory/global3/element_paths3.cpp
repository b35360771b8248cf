#include "theory/global3/element_paths3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/global3/local_maps3.hpp"
#include "theory/local3/local3.hpp"

namespace affinterp::global3 {

using Eigen::Index;
using Eigen::Matrix3d;
using global::LocalHomotopy;

ElementPaths3::ElementPaths3(const std::vector<Matrix3d>& maps, LocalHomotopy homotopy, global::RotationBranch branch,
                             const DualGraph3& graph)
    : homotopy_(homotopy), branch_(branch) {
  const Eigen::Matrix3Xd principal = decompose(maps);
  const bool consistent = branch == global::RotationBranch::consistent;
  const ConsistentLogs logs = consistent ? consistent_logs(graph, principal) : ConsistentLogs{principal, principal};
  use_logs(logs.omega, principal);
  if (turns()) split_ = consistent ? split_rotations(graph, logs) : unsplit_rotations(omega_);
}

ElementPaths3::ElementPaths3(const std::vector<Matrix3d>& maps, LocalHomotopy homotopy, const ElementPaths3& forward)
    : homotopy_(homotopy), branch_(forward.branch_) {
  const Eigen::Matrix3Xd principal = decompose(maps);
  Eigen::Matrix3Xd chosen(3, principal.cols());
  for (Index i = 0; i < principal.cols(); ++i)
    chosen.col(i) = local3::nearest_log<double>(principal.col(i), Eigen::Vector3d(-forward.omega_.col(i)));
  use_logs(chosen, principal);
  if (!turns()) return;
  split_ = branch_ == global::RotationBranch::consistent ? split_along(-forward.split_.carrier, omega_)
                                                         : unsplit_rotations(omega_);
}

Eigen::Matrix3Xd ElementPaths3::decompose(const std::vector<Matrix3d>& maps) {
  const auto m = static_cast<Index>(maps.size());
  Eigen::Matrix3Xd principal(3, m);
  omega_U_.resize(3, m), sigma_.resize(3, m), omega_V_.resize(3, m);
  stretch_.resize(maps.size());
  // Each element's decomposition alone: split over threads on large meshes, the same values on any number.
  const auto elements = static_cast<std::size_t>(m);
  global::for_each_range(elements, global::ranges_for(elements, decompositions_per_thread),
                         [&](std::size_t first, std::size_t last) {
                           for (auto i = static_cast<Index>(first); i < static_cast<Index>(last); ++i) {
                             const local3::Svd3<double> d = local3::svd3<double>(maps[static_cast<std::size_t>(i)]);
                             principal.col(i) = local3::rotation_log<double>(d.U * d.V.transpose());
                             stretch_[static_cast<std::size_t>(i)] =
                                 homotopy_ == LocalHomotopy::exp ? local3::log_stretch(d) : local3::polar3(d).S;
                             omega_U_.col(i) = local3::rotation_log<double>(d.U);
                             sigma_.col(i) = d.sigma;
                             omega_V_.col(i) = local3::rotation_log<double>(d.V.transpose());
                           }
                         });
  if (homotopy_ == LocalHomotopy::linear) A_ = maps;
  return principal;
}

void ElementPaths3::use_logs(const Eigen::Matrix3Xd& chosen, const Eigen::Matrix3Xd& principal) {
  omega_ = chosen;
  for (Index i = 0; i < omega_.cols(); ++i)
    if (omega_.col(i) != principal.col(i))
      omega_U_.col(i) =
          local3::nearest_log<double>(omega_U_.col(i), omega_U_.col(i) + omega_.col(i) - principal.col(i));
}

void ElementPaths3::maps_at(double t, std::span<Matrix3d> out, std::size_t threads,
                            const sym3::SymExpBatch& exp) const {
  if (homotopy_ == LocalHomotopy::exp) {
    exp_log_maps(
        [&](Index first, Index last, std::span<Eigen::Vector3d> Omega, std::span<Eigen::Vector3d> Eta,
            std::span<Matrix3d> Lambda) {
          for (Index i = first; i < last; ++i) {
            Omega[static_cast<std::size_t>(i - first)] = t * split_.carrier.col(i);
            Eta[static_cast<std::size_t>(i - first)] = t * split_.remainder.col(i);
            Lambda[static_cast<std::size_t>(i - first)] = t * stretch_[static_cast<std::size_t>(i)];
          }
        },
        out, threads, exp);
    return;
  }
  global::for_each_range(out.size(), threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) {
      const auto i = static_cast<Index>(s);
      switch (homotopy_) {
        case LocalHomotopy::linear:
          out[s] = local3::LinearHomotopy3<double>{A_[s]}(t);
          break;
        case LocalHomotopy::polar:  // R_i(t)((1 − t)I + tS_i)
          out[s] = local3::rotation_exp_product<double>(Eigen::Vector3d(t * split_.carrier.col(i)),
                                                        Eigen::Vector3d(t * split_.remainder.col(i))) *
                   ((1 - t) * Matrix3d::Identity() + t * stretch_[s]);
          break;
        default:
          out[s] = local3::SvdHomotopy3<double>{omega_U_.col(i), sigma_.col(i), omega_V_.col(i)}(t);
      }
    }
  });
}

}  // namespace affinterp::global3
