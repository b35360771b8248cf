#pragma once
// A sparse LDLᴴ (or LLᴴ) factorisation of a Hermitian positive definite K (real symmetric, or complex
// Hermitian for the complex form of hermitian_form.hpp), behind one interface so that the minimiser does
// not know which back-end it holds:
//   - Eigen's SimplicialLDLT (always available): the faster one on small meshes, where the supernodes
//     stay too small for BLAS-3 kernels to pay (octopus, 34,458 unknowns: numeric factorisation 23 ms
//     against 63–72 ms for CHOLMOD's supernodal LLᴴ, see hermitian_form.hpp);
//   - CHOLMOD's supernodal Cholesky (SuiteSparse; built in when CMake finds it, AFFINTERP_HAS_CHOLMOD),
//     3–4× faster to factor from about half a million triangles on (issue 19: 725 × 725 grid, 1.05 M
//     triangles, 2 cores: real 1.5–1.9 s against 5.8 s, complex 2.8 s against 10.3 s).
// The symbolic analysis (fill-reducing ordering, elimination tree or supernodes) is done once for the
// pattern and reused by every numeric factorisation.
#include "theory/global/options.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>

namespace affinterp::global {

template <class Scalar>
class SparseFactor {
 public:
  using SparseMatrix = Eigen::SparseMatrix<Scalar>;
  /// Right-hand sides and solutions: one row per unknown, so that a solve visits each entry of the factor
  /// once for all its columns (E^F's x and y, or a frame's z and the barycentre's column).
  using Block = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  virtual ~SparseFactor() = default;
  /// The symbolic analysis of K's pattern (its lower triangle is read).
  virtual void analyse(const SparseMatrix& K) = 0;
  /// The numeric factorisation of K (same pattern as analysed). False when K is not numerically positive
  /// definite: a pivot not above 10⁻¹² times the largest (a ratio, so whatever the mesh's units or size).
  virtual bool factorise(const SparseMatrix& K) = 0;
  /// X ← K⁻¹ X. Safe to call from several threads at once on one factor.
  virtual void solve_in_place(Block& X) const = 0;
  /// A copy holding the same analysis and factor: a workspace for another thread.
  virtual std::unique_ptr<SparseFactor> clone() const = 0;
  virtual SparseBackEnd back_end() const = 0;
  /// The bytes the factor's numeric values and indices take (for sizing parallel workspaces).
  virtual double factor_bytes() const = 0;
};

/// Unknowns from which CHOLMOD's supernodal factor is chosen when it is built in (measured on this
/// machine kind by bench_scale's scale_backend benchmarks, see experiments/apps/bench/bench_scale.cpp).
inline constexpr Eigen::Index cholmod_from_unknowns = 100'000;

/// Whether this build has the CHOLMOD back-end.
bool has_cholmod();

/// The back-end for `unknowns` unknowns: CHOLMOD from cholmod_from_unknowns on when built in, else Eigen's.
template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(Eigen::Index unknowns);
/// The named back-end (for benchmarks comparing them); std::invalid_argument if it is not built in.
template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(SparseBackEnd back_end);

}  // namespace affinterp::global
