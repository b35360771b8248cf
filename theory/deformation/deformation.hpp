#pragma once
// The deformation application of thesis §3.3–3.4 (Fig. 3.3), rebuilt in 3D: Kaji's local interpolation
// A(t) = R^t S^t (Kaji eq. (3)) per triangle, with S^t = exp(t log S) through a 3×3 symmetric matrix
// exponential, followed by a global Poisson-style least-squares solve for the vertex positions
// (Xu et al. [14]; Kaji §4 with the energy E^F). Only the per-frame exponential depends on the
// algorithm under test, as in the thesis, which replaced "the exponential part" of the deformer.
#include "theory/deformation/mesh3.hpp"
#include "theory/sym3/exp_batch.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <vector>

namespace affinterp::sym3 {

class Deformation3 {
 public:
  /// Precomputes, once for all frames: per triangle i the deformation gradient F_i = [e1' e2' n'][e1 e2 n]⁻¹
  /// (edges from the first corner, n the unit normal), its polar decomposition F_i = R_i S_i (R_i as
  /// axis and angle, log S_i from the SVD), and the sparse Cholesky factor of the global system.
  /// Throws std::invalid_argument when the meshes differ in connectivity, a triangle is degenerate or
  /// the mesh is not connected.
  Deformation3(const Mesh3& source, const Mesh3& target);

  /// The vertex positions at time t: A_i(t) = R_i^t exp(t log S_i) with `exp`, then the positions x that
  /// minimise Σ_i area_i Σ_{edges ab of i} ‖(x_b − x_a) − A_i(t)(p_b − p_a)‖² with vertex 0 moving on
  /// the straight line from its source to its target position.
  Eigen::Matrix3Xd interpolate(double t, const SymExpBatch& exp);

  Eigen::Index triangle_count() const { return source_.triangle_count(); }

 private:
  Mesh3 source_;
  Eigen::Vector3d anchor_source_, anchor_target_;
  std::vector<double> area_;
  std::vector<Eigen::Vector3d> axis_;                          ///< rotation axis of R_i
  std::vector<double> angle_;                                  ///< rotation angle of R_i, in [0, π]
  std::vector<Eigen::Matrix3d> log_S_;                         ///< log S_i
  Eigen::SparseMatrix<double> coupling_;                       ///< the anchor's column of the system, free rows
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;  ///< the system without the anchor
  // Per-frame scratch space.
  std::vector<Eigen::Matrix3d> t_log_S_, S_t_;
};

}  // namespace affinterp::sym3
