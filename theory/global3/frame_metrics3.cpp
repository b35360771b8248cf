#include "theory/global3/frame_metrics3.hpp"

#include "theory/global3/element_maps3.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace affinterp::global3 {

namespace {

struct ElementQuality {
  double ratio, distortion, measure;
};

/// B_i's signed measure ratio and distortion, and the frame element's measure.
ElementQuality element_quality(const Mesh3& source, const Mesh3& framed, Eigen::Index i, const Eigen::Matrix3d& A) {
  const Eigen::MatrixXd E = element_edges(source, i), X = element_edges(framed, i);
  const Eigen::MatrixXd B = X * (E.transpose() * E).inverse() * E.transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(B);
  const Eigen::Index d = E.cols();
  const double sigma_min = svd.singularValues()[d - 1];
  const double distortion =
      sigma_min > 0 ? svd.singularValues()[0] / sigma_min : std::numeric_limits<double>::infinity();
  if (d == 3) {
    const double det = X.determinant() / E.determinant();
    return {det, distortion, X.determinant() / 6};
  }
  const Eigen::Vector3d n_p = Eigen::Vector3d(E.col(0)).cross(Eigen::Vector3d(E.col(1)));
  const Eigen::Vector3d n_x = Eigen::Vector3d(X.col(0)).cross(Eigen::Vector3d(X.col(1)));
  const double ratio = n_x.norm() / n_p.norm();
  return {n_x.dot(A * n_p) > 0 ? ratio : -ratio, distortion, n_x.norm() / 2};
}

}  // namespace

FrameMetrics3 frame_metrics3(const Mesh3& source, const Eigen::Matrix3Xd& frame,
                             std::span<const Eigen::Matrix3d> local_maps, std::span<const unsigned char> near) {
  if (frame.cols() != source.vertex_count()) throw std::invalid_argument("frame_metrics3: one column a vertex");
  if (!local_maps.empty() && static_cast<Eigen::Index>(local_maps.size()) != source.element_count())
    throw std::invalid_argument("frame_metrics3: one local map an element");
  if (!near.empty() && static_cast<Eigen::Index>(near.size()) != source.element_count())
    throw std::invalid_argument("frame_metrics3: one mask entry an element");
  const Mesh3 framed{frame, source.elements};
  FrameMetrics3 metrics;
  metrics.min_ratio = std::numeric_limits<double>::infinity();
  metrics.max_ratio = -metrics.min_ratio;
  double measure = 0;
  for (Eigen::Index i = 0; i < source.element_count(); ++i) {
    const Eigen::Matrix3d A =
        local_maps.empty() ? Eigen::Matrix3d::Identity() : local_maps[static_cast<std::size_t>(i)];
    const ElementQuality q = element_quality(source, framed, i, A);
    if (q.ratio <= 0) {
      metrics.inverted.push_back(i);
      metrics.inverted_near_folds += !near.empty() && near[static_cast<std::size_t>(i)];
    }
    metrics.min_ratio = std::min(metrics.min_ratio, q.ratio);
    metrics.max_ratio = std::max(metrics.max_ratio, q.ratio);
    metrics.max_distortion = std::max(metrics.max_distortion, q.distortion);
    metrics.mean_distortion += q.distortion / static_cast<double>(source.element_count());
    measure += q.measure;
  }
  metrics.inverted_elements = static_cast<Eigen::Index>(metrics.inverted.size());
  metrics.measure_ratio = measure / element_measures(source).sum();
  return metrics;
}

}  // namespace affinterp::global3
