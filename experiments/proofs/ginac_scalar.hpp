#pragma once
// GiNaC expressions as an Eigen scalar, so that the suite's templated algebra (theory/global's E^R, theory/sym3's
// Viète and spectral formulas) can be instantiated over symbols: the identities of the proofs are then built
// from the very functions the claims check, and a bug in theory/ shows up in the proof.
#include <ginac/ginac.h>

#include <Eigen/Core>
#include <string>

namespace Eigen {

template <>
struct NumTraits<GiNaC::ex> : GenericNumTraits<GiNaC::ex> {
  using Real = GiNaC::ex;
  using NonInteger = GiNaC::ex;
  using Literal = GiNaC::ex;
  using Nested = GiNaC::ex;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 10,
    AddCost = 10,
    MulCost = 10,
  };
};

}  // namespace Eigen

namespace affinterp::proofs {

template <int Rows, int Cols>
using SymbolicMatrix = Eigen::Matrix<GiNaC::ex, Rows, Cols>;

/// The Rows × Cols matrix of fresh symbols `<prefix><row><col>` (1-based), e.g. a11, a12, a21, a22.
template <int Rows, int Cols>
SymbolicMatrix<Rows, Cols> symbolic_matrix(const std::string& prefix) {
  SymbolicMatrix<Rows, Cols> M;
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Cols; ++c) M(r, c) = GiNaC::symbol(prefix + std::to_string(r + 1) + std::to_string(c + 1));
  return M;
}

/// The same matrix as a GiNaC::matrix (an expression), as the identity prover compares matrices.
template <int Rows, int Cols>
GiNaC::matrix to_ginac(const SymbolicMatrix<Rows, Cols>& M) {
  GiNaC::matrix m(Rows, Cols);
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Cols; ++c) m(r, c) = M(r, c);
  return m;
}

}  // namespace affinterp::proofs
