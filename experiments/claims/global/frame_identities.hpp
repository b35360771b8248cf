#pragma once
// Kaji §4's E^F frame problem for every mesh, from identities of one triangle: Σ_i w_i E^F(A_i, B_i)
// is a sum over triangles (w_i > 0), so what an identity says of one triangle's quadratic form holds for the
// assembled G, u of any mesh. The identities use theory/global's linear_part_operator and frobenius_quadratic
// over symbols, with the products P̂ D and AᵀA left to the checkers:
//   operator        P̂ D = [I; 0] for D = linear_part_operator(p), P̂ = [p; 1 1 1] (eq. (1)), so 1ᵀD = 0 and
//                   rank D = 2: the left kernel of D is spanned by 1ᵀ;
//   quadratic-part  xᵀHx = ‖V D‖²,   linear-part  gᵀx = −2⟨A, V D⟩,   constant  c = tr(AᵀA) = ‖A‖²
//                   (so xᵀHx + gᵀx + c = ‖A − V D‖² = E^F(A, B), B = V D), for every D with 1ᵀD = 0;
//   translation-H, translation-g   Hτ = 0 and gᵀτ = 0 for τ = (τx, τy, τx, τy, τx, τy).
// Hence, for a mesh in one connected piece: Gτ = 0 and uᵀτ = 0 for every translation τ; vᵀGv = Σ w_i ‖V_i D_i‖² = 0
// forces every V_i D_i = 0, i.e. V_i = τ_i 1ᵀ (each triangle collapsed to a point), the same τ across shared
// vertices: the kernel of G is exactly the translations (rank 2n − 2), and a pinned vertex ‖v_1 − r‖² adds ‖v_1‖²,
// positive on every nonzero translation, so G + pin is positive definite and the minimiser unique. The argument
// from one triangle to the mesh (sum, connectivity) is the one step not decided by a checker.
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/global/local_error.hpp"
#include "theory/global/triangle_map.hpp"
#include "theory/local/affine_map.hpp"

#include <string>
#include <vector>

namespace affinterp::claims::frame_identities {

/// The identities above, over symbols p (source corners), v (frame corners), a (A), d (D) and tx, ty (τ).
inline std::vector<proofs::Identity> identities() {
  using X = GiNaC::ex;
  const global::Corners<X> p = proofs::symbolic_matrix<2, 3>("p"), V = proofs::symbolic_matrix<2, 3>("v");
  const Eigen::Matrix<X, 2, 2> A = proofs::symbolic_matrix<2, 2>("a");
  // Every D with 1ᵀD = 0: rows d1, d2 free, row 0 = −d1 − d2.
  const Eigen::Matrix<X, 2, 2> free_rows = proofs::symbolic_matrix<2, 2>("d");
  global::LinearPartOperator<X> D;
  D.row(0) = -free_rows.row(0) - free_rows.row(1);
  D.bottomRows<2>() = free_rows;
  const global::TriangleQuadratic<X> form = global::frobenius_quadratic<X>(D, A);
  Eigen::Matrix<X, 6, 1> x, tau;
  const GiNaC::symbol tx("tx"), ty("ty");
  for (int k = 0; k < 3; ++k) x[2 * k] = V(0, k), x[2 * k + 1] = V(1, k), tau[2 * k] = tx, tau[2 * k + 1] = ty;
  const Eigen::Matrix<X, 2, 2> B = V.lazyProduct(D);
  const X AtA = proofs::product(proofs::transposed(proofs::to_ginac(A)), proofs::to_ginac(A));
  Eigen::Matrix<X, 3, 2> I_over_zero;
  I_over_zero << X(1), X(0), X(0), X(1), X(0), X(0);
  return {
      {"operator", "P̂ D = [I; 0] for D = linear_part_operator(p), P̂ = [p; 1 1 1]",
       proofs::product(proofs::to_ginac<3, 3>(::affinterp::local::homogeneous(p)),
                       proofs::to_ginac<3, 2>(global::linear_part_operator(p))),
       proofs::to_ginac(I_over_zero)},
      {"quadratic-part", "xᵀHx = ‖V D‖² (frobenius_quadratic, 1ᵀD = 0)", X(x.dot(form.H.lazyProduct(x))),
       X(B.squaredNorm())},
      {"linear-part", "gᵀx = −2⟨A, V D⟩", X(form.g.dot(x)), X(-2 * global::frobenius_inner(A, B))},
      {"constant", "c = tr(AᵀA) = ‖A‖² (so xᵀHx + gᵀx + c = ‖A − V D‖²)", form.c,
       proofs::entry(AtA, 0) + proofs::entry(AtA, 3)},
      {"translation-H", "H τ = 0 for τ = (tx, ty, tx, ty, tx, ty)", proofs::to_ginac<6, 1>(form.H.lazyProduct(tau)),
       proofs::to_ginac<6, 1>(Eigen::Matrix<X, 6, 1>::Constant(X(0)))},
      {"translation-g", "gᵀτ = 0", X(form.g.dot(tau)), X(0)},
  };
}

/// The method line of a proof built on these identities.
inline const char* method() {
  return "identities of one triangle over symbols from theory/global's linear_part_operator and "
         "frobenius_quadratic: P̂D = [I; 0] (so 1ᵀD = 0, rank D = 2), the form is ‖A − VD‖², Hτ = 0 and gᵀτ = 0; "
         "for every mesh Σ w_i E^F sums them, vᵀGv = Σ w_i‖V_iD_i‖² vanishes only where every triangle is one "
         "point, i.e. (one connected piece) on the translations; a pinned vertex makes G + pin positive definite. "
         "That sum-and-connectivity step is Lemma L23 (positive weights, non-degenerate source triangles, a connected "
         "mesh)";
}

}  // namespace affinterp::claims::frame_identities
