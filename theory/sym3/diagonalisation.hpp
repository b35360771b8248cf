#pragma once
// Thesis §3.1.1 (Algorithm 1, diagonalisation): exp S = P exp(D) Pᵀ, with the eigen-decomposition from
// each of Eigen's two symmetric solvers: the QR iteration (compute) and the closed form (computeDirect).
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

Vec3 eigenvalues_eigen_qr(const Mat3& S);
Vec3 eigenvalues_eigen_direct(const Mat3& S);
Mat3 exp_eigen_qr_diag(const Mat3& S);
Mat3 exp_eigen_direct_diag(const Mat3& S);

}  // namespace affinterp::sym3
