#include "theory/deformation/deformation.hpp"

#include "theory/linalg/symmetric.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <stdexcept>
#include <string>

namespace affinterp::sym3 {

using Eigen::Index;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

/// [e1 e2 n] of triangle i: its edges from the first corner and its unit normal.
Matrix3d triangle_frame(const Mesh3& mesh, Index i) {
  const Vector3d e1 = mesh.corner(i, 1) - mesh.corner(i, 0), e2 = mesh.corner(i, 2) - mesh.corner(i, 0);
  const Vector3d normal = e1.cross(e2);
  const double length = normal.norm();
  if (!(length > 0)) throw std::invalid_argument("triangle " + std::to_string(i) + " is degenerate");
  Matrix3d frame;
  frame << e1, e2, normal / length;
  return frame;
}

constexpr int edge_ends[3][2] = {{0, 1}, {1, 2}, {2, 0}};

}  // namespace

Deformation3::Deformation3(const Mesh3& source, const Mesh3& target) : source_(source) {
  if (target.vertex_count() != source.vertex_count() || target.triangles != source.triangles)
    throw std::invalid_argument("source and target meshes differ in connectivity");
  const Index m = source.triangle_count(), n = source.vertex_count();
  if (n < 2) throw std::invalid_argument("the mesh needs at least two vertices");
  anchor_source_ = source.vertices.col(0);
  anchor_target_ = target.vertices.col(0);

  area_.resize(m);
  axis_.resize(m);
  angle_.resize(m);
  log_S_.resize(m);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * m);
  for (Index i = 0; i < m; ++i) {
    const Matrix3d P = triangle_frame(source, i);
    const Matrix3d F = triangle_frame(target, i) * P.inverse();
    // det F > 0 (both frames are positively oriented), so F = R S with R ∈ SO(3), S positive definite.
    // Polar decomposition F = R S from F = U Σ Vᵀ: R = U Vᵀ, S = V Σ Vᵀ, so log S = V log Σ Vᵀ.
    const Eigen::JacobiSVD<Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::AngleAxisd rotation(Matrix3d(svd.matrixU() * svd.matrixV().transpose()));
    axis_[i] = rotation.axis();
    angle_[i] = rotation.angle();
    log_S_[i] = linalg::congruence(svd.matrixV(), svd.singularValues().array().log().matrix());
    area_[i] = P.col(0).cross(P.col(1)).norm() / 2;
    for (const auto& [a, b] : edge_ends) {
      const Index va = source.triangles(a, i), vb = source.triangles(b, i);
      entries.emplace_back(va, va, area_[i]);
      entries.emplace_back(vb, vb, area_[i]);
      entries.emplace_back(va, vb, -area_[i]);
      entries.emplace_back(vb, va, -area_[i]);
    }
  }
  // Normal equations L x = b of the energy; vertex 0 is prescribed, so the free vertices 1 … n−1
  // solve L_ff x_f = b_f − L_f0 x_0 with L_ff factored once (it does not depend on t).
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> L_free = L.bottomRightCorner(n - 1, n - 1);
  coupling_ = L.bottomLeftCorner(n - 1, 1);
  solver_.compute(L_free);
  if (solver_.info() != Eigen::Success)
    throw std::invalid_argument("the global system is singular (is the mesh connected?)");
  t_log_S_.resize(m);
  S_t_.resize(m);
}

Eigen::Matrix3Xd Deformation3::interpolate(double t, const SymExpBatch& exp) {
  const Index m = source_.triangle_count(), n = source_.vertex_count();
  for (Index i = 0; i < m; ++i) t_log_S_[i] = t * log_S_[i];
  exp(t_log_S_, S_t_);

  Eigen::MatrixX3d b = Eigen::MatrixX3d::Zero(n, 3);
  for (Index i = 0; i < m; ++i) {
    const Matrix3d A = Eigen::AngleAxisd(t * angle_[i], axis_[i]).toRotationMatrix() * S_t_[i];
    for (const auto& [a, c] : edge_ends) {
      const Index va = source_.triangles(a, i), vc = source_.triangles(c, i);
      const Vector3d g = area_[i] * (A * (source_.vertices.col(vc) - source_.vertices.col(va)));
      b.row(vc) += g.transpose();
      b.row(va) -= g.transpose();
    }
  }
  const Vector3d anchor = (1 - t) * anchor_source_ + t * anchor_target_;
  const Eigen::MatrixX3d b_free = b.bottomRows(n - 1) - coupling_ * anchor.transpose();
  Eigen::Matrix3Xd x(3, n);
  x.col(0) = anchor;
  x.rightCols(n - 1) = solver_.solve(b_free).transpose();
  return x;
}

}  // namespace affinterp::sym3
