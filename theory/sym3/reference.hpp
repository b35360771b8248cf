#pragma once
// High-precision ground truth for S ∈ Sym(3), by two independent methods computed at 100 significant
// digits and compared at 50 (tests cross-check them):
//  1. eigen-decomposition by the cyclic Jacobi iteration, exp S = V exp(Λ) Vᵀ (thesis Prop. 3.1.2);
//  2. the Taylor series (thesis Def. 3.1.2) with scaling and squaring.
#include "theory/exact/rational.hpp"
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

using Mat3R50 = Eigen::Matrix<exact::Real50, 3, 3>;
using Vec3R50 = Eigen::Matrix<exact::Real50, 3, 1>;
using Mat3R100 = Eigen::Matrix<exact::Real100, 3, 3>;
using Vec3R100 = Eigen::Matrix<exact::Real100, 3, 1>;

/// S = V diag(lambda) Vᵀ, lambda ascending, V orthogonal (to about 10⁻⁹⁵).
struct ReferenceEigen {
  Vec3R100 lambda;
  Mat3R100 V;
};

/// Cyclic Jacobi rotations until the off-diagonal part is below 10⁻⁹⁸ ‖S‖_F. Every reference below
/// requires S exactly symmetric and throws std::invalid_argument otherwise.
ReferenceEigen reference_eigen(const Mat3R100& S);
/// Method 1: V exp(Λ) Vᵀ at 100 digits.
Mat3R100 exp_by_eigen(const Mat3R100& S);
/// Method 2: Σ (S/2^s)^k / k! to 10⁻¹⁰⁵ relative, squared s times, at 100 digits.
Mat3R100 exp_by_taylor(const Mat3R100& S);

/// The double matrix S exactly in Real100.
Mat3R100 to_real100(const Mat3& S);
/// A rational matrix rounded to 100 digits.
Mat3R100 to_real100(const exact::Mat3Q& S);

/// Ground truth for exp of a double matrix, rounded to 50 digits: method 1.
Mat3R50 reference_exp(const Mat3& S);
/// The same by method 2.
Mat3R50 reference_exp_taylor(const Mat3& S);
/// Eigenvalues of a double matrix, ascending, rounded to 50 digits.
Vec3R50 reference_eigenvalues(const Mat3& S);

/// ‖X − E‖_F / ‖E‖_F, evaluated at 50 digits and returned as a double.
double relative_error(const Mat3& X, const Mat3R50& E);
/// max_i |x_i − e_i| / max(1, max_i |e_i|), at 50 digits (eigenvalues); NaN if x is not finite.
double eigenvalue_error(const Vec3& x, const Vec3R50& e);

}  // namespace affinterp::sym3
