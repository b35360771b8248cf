#include "theory/sym3/diagonalisation.hpp"

#include <Eigen/Eigenvalues>

namespace affinterp::sym3 {
namespace {

using Solver = Eigen::SelfAdjointEigenSolver<Mat3>;

/// Proposition 3.1.2: exp S = P exp(D) Pᵀ.
Mat3 exp_diagonalised(const Solver& solver) {
  const Mat3& P = solver.eigenvectors();
  return P * solver.eigenvalues().array().exp().matrix().asDiagonal() * P.transpose();
}

}  // namespace

Vec3 eigenvalues_eigen_qr(const Mat3& S) { return Solver(S, Eigen::EigenvaluesOnly).eigenvalues(); }

Vec3 eigenvalues_eigen_direct(const Mat3& S) {
  Solver solver;
  solver.computeDirect(S, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();
}

Mat3 exp_eigen_qr_diag(const Mat3& S) { return exp_diagonalised(Solver(S)); }

Mat3 exp_eigen_direct_diag(const Mat3& S) {
  Solver solver;
  solver.computeDirect(S);
  return exp_diagonalised(solver);
}

}  // namespace affinterp::sym3
