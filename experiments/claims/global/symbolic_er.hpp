#pragma once
// Kaji's E^R (Appendix) over symbols: the suite's own templates of theory/global/local_error.hpp instantiated
// with GiNaC expressions, for the identities that prove the kaji.er.* claims for all reals.
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/global/local_error.hpp"

#include <ginac/ginac.h>
#include <Eigen/LU>

namespace affinterp::claims::symbolic_er {

using Mat2X = proofs::SymbolicMatrix<2, 2>;

/// A = [[a11, a12], [a21, a22]] and B = [[b11, b12], [b21, b22]], every entry a symbol.
struct Pair {
  Mat2X A = proofs::symbolic_matrix<2, 2>("a"), B = proofs::symbolic_matrix<2, 2>("b");
};

/// xI + yJ (J = R_{π/2}): every s R_δ is one (Kaji Appendix).
inline Mat2X similarity(const GiNaC::ex& x, const GiNaC::ex& y) {
  return local::scaled(x, local::identity2<GiNaC::ex>()) + local::scaled(y, global::rotation_J<GiNaC::ex>());
}

/// A B as a product the identity checkers perform: each entry an entry node of the product of A and B.
inline Mat2X times(const Mat2X& A, const Mat2X& B) {
  const GiNaC::ex AB = proofs::product(proofs::to_ginac(A), proofs::to_ginac(B));
  Mat2X entries;
  for (unsigned k = 0; k < 4; ++k) entries(k / 2, k % 2) = proofs::entry(AB, k);
  return entries;
}

/// ‖A‖², ⟨A, B⟩ and ⟨JA, B⟩ (Kaji Appendix).
inline GiNaC::ex norm2(const Mat2X& A) { return global::frobenius_inner(A, A); }
inline GiNaC::ex inner(const Mat2X& A, const Mat2X& B) { return global::frobenius_inner(A, B); }
inline GiNaC::ex inner_J(const Mat2X& A, const Mat2X& B) {
  return global::frobenius_inner(Mat2X(global::rotation_J<GiNaC::ex>().lazyProduct(A)), B);
}

/// E^R(A, B) as theory/global prints it (the Appendix's closed form).
inline GiNaC::ex E_R(const Mat2X& A, const Mat2X& B) { return global::similarity_error<GiNaC::ex>(A, B); }

}  // namespace affinterp::claims::symbolic_er
