#pragma once
// The quadratic form of the global error function at time t (Kaji Appendix, "Efficiency"): the local
// errors of all triangles — and, for the symmetrised energy, those of the reverse problem Q → P at
// time 1 − t — plus the constraint terms, in the complex form z*H(t)z + Re(ũ(t)*z) + c(t) of
// hermitian_form.hpp (z_k = v_kx + i v_ky).
//
// When every triangle's error is E^F, H = L is real and does not involve A_i(t) (G = L ⊗ I₂): it is
// assembled once. Otherwise each triangle's H_i = H₀ − c v v* (hermitian_local_error.hpp) has a part H₀
// that does not involve A_i(t): their sum with the constraint terms is assembled once, and H(t) is that less
// the triangles' rank-one terms at t, refilled for each t in a fixed sparsity pattern whose value slots are
// precomputed. The assembly does not change after construction: the caller owns the matrix it fills.
#include "theory/global/constraint_terms.hpp"
#include "theory/global/frame_energy.hpp"
#include "theory/global/frame_quadratic.hpp"
#include "theory/global/local_error.hpp"
#include "theory/global/local_paths.hpp"
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"
#include "theory/global/sparse_minimiser.hpp"
#include "theory/global/vertex_stars.hpp"

#include <Eigen/SparseCore>

#include <array>
#include <complex>
#include <optional>
#include <vector>

namespace affinterp::global {

/// One local error E_i(A_i(s), B_i(x)), its reference corners and weights.
struct TriangleTerm {
  std::array<Eigen::Index, 3> vertex;
  Eigen::Matrix<double, 3, 2> D;  ///< B_i = V D (eq. (1))
  Corners<double> corners;        ///< the reference triangle (source, or target for the reverse problem)
  double weight = 1.0;            ///< its area when area weighted, else 1
  double frobenius_share = 1.0;   ///< w_i: E^F's share of the blend
};

class FrameAssembly {
 public:
  using SparseMatrix = Eigen::SparseMatrix<std::complex<double>>;

  /// `reverse` (the reverse problem's local paths) only for the symmetrised energy.
  FrameAssembly(const Mesh& source, const Mesh& target, const InterpolationOptions& options, const LocalPaths& forward,
                const LocalPaths* reverse, std::vector<ConstraintTerm> constraints);

  /// H is real and the same for every t (no triangle carries an E^R or E^S part).
  bool isotropic() const { return isotropic_; }
  /// H's sparsity pattern, lower triangle: the vertex pairs of every triangle and sparse constraint term.
  /// The matrix that matrix_at fills is a copy of it.
  const SparseMatrix& pattern() const { return pattern_; }
  /// Writes the lower triangle of H(t) without the dense term, grounded at vertex 0 when dense_term() says
  /// so (column 0's off-diagonal entries zero: sparse_minimiser.hpp), into the values of `H`, which has the
  /// structure of pattern(): one matrix serves every frame. The triangles' terms are computed on `threads`
  /// threads (the same H whatever their number).
  void matrix_at(double t, SparseMatrix& H, std::size_t threads = 1) const;
  /// −ũ(t)/2, so that H z = −ũ/2 at the minimiser; computed on `threads` threads (the same vector whatever
  /// their number: parallel_ranges.hpp).
  Eigen::VectorXcd right_hand_side_at(double t, std::size_t threads = 1) const;
  /// The dense constraint term (the barycentre), which matrix_at leaves out, if there is one.
  const std::optional<DenseTerm>& dense_term() const { return dense_; }

  /// The whole form at t, real and dense (for inspection on small meshes).
  FrameQuadratic dense_quadratic_at(double t) const;
  /// E_t at the vertices `v` from the local errors' closed forms (local_error.hpp), not from H(t): the value
  /// vᵀG(t)v + vᵀu(t) + c(t) of dense_quadratic_at, computed in O(triangles).
  FrameEnergy energy_at(double t, const Eigen::Matrix2Xd& v) const;

 private:
  TriangleQuadratic<double> triangle_quadratic(Eigen::Index i, double t) const;
  void build_pattern();

  Energy energy_;
  Eigen::Index n_;
  bool isotropic_;
  const LocalPaths& forward_;
  const LocalPaths* reverse_;
  std::vector<TriangleTerm> forward_terms_, reverse_terms_;
  std::vector<ConstraintTerm> constraints_;
  VertexStars stars_;  ///< of the source's triangles (the same list as the target's)
  SparseMatrix pattern_;
  std::vector<int> triangle_slots_;      ///< per triangle, 9 slots into pattern_'s values (−1: upper half)
  std::vector<double> constant_values_;  ///< the sparse constraint terms and every triangle's H₀ (real)
  std::optional<DenseTerm> dense_;
};

}  // namespace affinterp::global
