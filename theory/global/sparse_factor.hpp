#pragma once
// A sparse LDLᴴ (or LLᴴ) factorisation of a Hermitian positive definite K (real symmetric, or complex
// Hermitian for the complex form of hermitian_form.hpp), behind one interface so that the minimiser does
// not know which back-end it holds:
//   - our simplicial up-looking LDLᴴ (simplicial_factor.hpp, always available): the faster one to factorise on
//     small meshes, where the supernodes stay too small for BLAS-3 kernels to pay;
//   - CHOLMOD's supernodal Cholesky (SuiteSparse; built in when CMake finds it, AFFINTERP_HAS_CHOLMOD), on
//     an optimised BLAS (experiments/setup.sh installs OpenBLAS) the faster one to factorise on large
//     meshes (cholmod_from_unknowns).
// The symbolic analysis (fill-reducing ordering, elimination tree or supernodes) is done once for the
// pattern and reused by every numeric factorisation.
#include "theory/global/options.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <type_traits>

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
  /// The numeric factorisation of K (same pattern as analysed), on up to `threads` threads where the back-end
  /// can (the same factor whatever their number). False when K is not numerically positive definite: a pivot
  /// not above 10⁻¹² times the largest (a ratio, so whatever the mesh's units or size).
  virtual bool factorise(const SparseMatrix& K, std::size_t threads) = 0;
  /// K into this factor and K_other (same pattern) into `other`, a clone of this one, on one thread: true when
  /// both are positive definite. Each is the factor that factorise gives; a back-end that can do the two in one
  /// pass does (simplicial_factor.hpp), the others one after the other.
  virtual bool factorise_two(const SparseMatrix& K, SparseFactor& other, const SparseMatrix& K_other) {
    const bool first = factorise(K, 1);
    return other.factorise(K_other, 1) && first;
  }
  /// Whether factorise_two does the two in one pass, faster than one after the other.
  virtual bool two_in_one_pass() const { return false; }
  /// X ← K⁻¹ X, on up to `threads` threads where the back-end can (the same X whatever their number). Safe
  /// to call from several threads at once on one factor.
  virtual void solve_in_place(Block& X, std::size_t threads) const = 0;
  /// A copy holding the same analysis and factor: a workspace for another thread.
  virtual std::unique_ptr<SparseFactor> clone() const = 0;
  virtual SparseBackEnd back_end() const = 0;
  /// The bytes the factor's numeric values and indices take (for sizing parallel workspaces).
  virtual double factor_bytes() const = 0;
};

/// Unknowns (vertices) from which CHOLMOD's supernodal factor is chosen when it is built in: where the ratio of the
/// simplicial back-end's cost to CHOLMOD's crosses 1, taken as a power of the size between the two sizes
/// bench_scale's backend_factor and backend_solve measure on one thread (the man at 261k and 1M triangles, 132k
/// and 525k unknowns; CHOLMOD on OpenBLAS without OpenMP teams, cholmod_factor.cpp). The simplicial factor also
/// splits one frame's rows over two threads, which this leaves out. Re-run those benchmarks to move them:
///  - real systems, E^F's L, factored once and solved every frame: both solve alike (CHOLMOD's factor is turned
///    into the same kind of columns, cholmod_factor.hpp), so the factorisation decides: the simplicial one is
///    faster at 132k, CHOLMOD at 525k, crossing near 300,000;
///  - complex systems, refactorised every frame (E^R, E^S, blends): a factorisation and a solve, the simplicial
///    back-end a little faster at 132k and CHOLMOD about twice as fast at 525k, crossing near 170,000.
template <class Scalar>
inline constexpr Eigen::Index cholmod_from_unknowns = std::is_same_v<Scalar, double> ? 300'000 : 170'000;

/// Whether this build has the CHOLMOD back-end.
bool has_cholmod();

/// The back-end for `unknowns` unknowns: CHOLMOD from cholmod_from_unknowns<Scalar> on when built in, else the
/// simplicial one.
template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(Eigen::Index unknowns);
/// The named back-end (for benchmarks comparing them); std::invalid_argument if it is not built in.
template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(SparseBackEnd back_end);

}  // namespace affinterp::global
