#pragma once
// The preconditioned conjugate gradient method for A x = b, A Hermitian positive definite (Saad, Iterative
// Methods for Sparse Linear Systems, 2nd ed., Algorithm 9.1), with M⁻¹ the exact inverse of a nearby A: the
// per-frame solve of E^R-type energies, whose H(t) changes little from frame to frame, preconditioned by the
// Cholesky factor of an earlier frame's H (sparse_minimiser.hpp). With M close to A, z_k = M⁻¹ r_k is close
// to A⁻¹ r_k = x − x_k, the error itself: it is the stopping test, and x_k + z_k the answer.
#include <Eigen/Core>

#include <functional>

namespace affinterp::global {

struct CgLimits {
  /// Stop when ‖z_k‖_∞ ≤ tolerance · spread(x_k), spread the extent of x's real (and imaginary) parts: a
  /// ratio to the frame's size, whatever the mesh's units or position.
  double tolerance = 1e-11;
  /// Give up (not converged) after this many iterations, one preconditioner solve each.
  int max_iterations = 30;
};

struct CgOutcome {
  int iterations = 0;  ///< preconditioner solves after the first
  bool converged = false;
};

/// x ← A⁻¹ b from the guess in x. `apply(p, q)` sets q = A p; `precondition(r)` sets r ← M⁻¹ r.
template <class Scalar>
CgOutcome preconditioned_cg(const std::function<void(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&,
                                                     Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&)>& apply,
                            const std::function<void(Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&)>& precondition,
                            const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b,
                            Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x, const CgLimits& limits);

}  // namespace affinterp::global
