#pragma once
// The energies of thesis §2.3 for a pair of triangles, and the exact minimisation of a quadratic energy.
#include <ginac/ginac.h>

namespace affinterp::origin {

/// ‖M‖²_F, the sum of the squared entries.
GiNaC::ex frobenius_squared(const GiNaC::matrix& M);

/// E1(A1, A2, B1, B2) = ‖A1 − B1‖²_F + ‖A2 − B2‖²_F (thesis Def. 2.3.1: every origin at zero).
GiNaC::ex energy_E1(const GiNaC::matrix& A1, const GiNaC::matrix& A2, const GiNaC::matrix& B1, const GiNaC::matrix& B2);

/// E2(A1, A2, B1, B2, o1, o2) = E1(T(A1, −o1), T(A2, −o2), T(B1, −o1), T(B2, −o2)) (thesis Def. 2.3.2:
/// triangle i measured in coordinates whose origin is o_i).
GiNaC::ex energy_E2(const GiNaC::matrix& A1, const GiNaC::matrix& A2, const GiNaC::matrix& B1, const GiNaC::matrix& B2,
                    const GiNaC::matrix& o1, const GiNaC::matrix& o2);

struct Minimum {
  GiNaC::lst minimiser;  ///< relations unknown == value, in the order of the unknowns
  GiNaC::ex value;       ///< the energy at the minimiser, normalised (numerator/denominator)
};

/// The stationary point of an energy of degree ≤ 2 in `unknowns`: the unique solution of the normal
/// equations ∂E/∂u = 0 (a minimum when E is bounded below, as a sum of squares is). Coefficients may be
/// rational functions of other symbols; the solution is then a rational function of them.
/// Throws std::invalid_argument when E is not quadratic or the normal equations are singular.
Minimum minimise(const GiNaC::ex& energy, const GiNaC::lst& unknowns);

/// The normal equations ∂E/∂u = 0, one per unknown.
GiNaC::lst normal_equations(const GiNaC::ex& energy, const GiNaC::lst& unknowns);

}  // namespace affinterp::origin
