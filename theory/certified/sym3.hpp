#pragma once
// Certified references for S ∈ Sym(3) (thesis ch. 3): exp S, the eigenvalues, S^t and log S as balls
// with rigorous radii (Arb ball arithmetic), for any finite double matrix S taken exactly.
//
// Method ("exact rotation"): an approximate eigenbasis is computed by Jacobi at the working precision p
// and turned into a quaternion q rounded to p bits; R = R(q)/|q|² is then an exactly orthogonal rational
// matrix. In ball arithmetic T = Rᵀ S R is enclosed; with D = diag(mid T_ii) and η ≥ ‖T − D‖_F,
//  - eigenvalues: Weyl's theorem puts the k-th smallest eigenvalue of S within η of the k-th smallest d;
//  - f(S) = R f(T) Rᵀ and, for Hermitian matrices and the Frobenius norm, ‖f(T) − f(D)‖_F ≤ L ‖T − D‖_F
//    with L = sup |f′| on [min d − η, max d + η] (the Hilbert–Schmidt identity
//    ‖f(A) − f(B)‖²_F = Σ |f(αᵢ) − f(βⱼ)|² ‖PᵢQⱼ‖²_F); so f(S) lies within L η (Frobenius) of R f(D) Rᵀ,
//    which is itself computed in ball arithmetic.
// No eigenvalue gap is ever divided by: clustered and repeated eigenvalues are certified as tightly as
// distinct ones, and η ≈ 2⁻ᵖ ‖S‖ whatever the spectrum. The precision doubles (from 128 bits) until the
// radius meets the target. Where that needs more than max_bits the result says so (status too_wide):
// the balls are still valid, only wider.
//
// What it cannot certify cheaply: the relative accuracy of S^t and log S costs p ≈ log₂ κ₂(S) + the
// target's bits (κ₂ up to 2²¹⁰⁰ for double matrices: a few thousand bits, under a millisecond); the
// overflow of exp S is undecidable when an entry equals the largest double to within the radius.
//
// exp_taylor is an independent check of exp: Arb's arb_mat_exp (Taylor series with a rigorous tail bound,
// scaling and squaring). Its radius grows with ‖S‖ (each squaring doubles it) and it cannot evaluate
// e^λ for astronomically large λ, so it serves as a cross-check on moderate matrices only.
#include "theory/certified/ball.hpp"
#include "theory/sym3/algorithms.hpp"

namespace affinterp::certified {

using sym3::Mat3;
using sym3::Vec3;

struct Options {
  /// Stop when every radius is at most this fraction of the value's norm (‖F‖_F for matrices,
  /// max |λ| for eigenvalues).
  double relative_radius = 0x1p-110;
  /// Working precision to start from, and the most to try (doubling in between).
  long start_bits = 128;
  long max_bits = 16384;
};

enum class Status {
  certified,  ///< every radius within the target; for exp, every entry certainly finite in double
  overflows,  ///< exp only: an entry of exp S certainly rounds to ±∞ in double (balls may be [± ∞])
  not_spd,    ///< S^t, log S only: S is not positive definite (decided exactly; no balls)
  too_wide,   ///< the target was not reached by max_bits, or exp S's overflow is undecided: balls valid
};

struct CertifiedMatrix {
  Status status = Status::too_wide;
  Balls value;    ///< 3×3; contains the true matrix whenever status != not_spd
  long bits = 0;  ///< the working precision that produced it
};

struct CertifiedEigenvalues {
  Status status = Status::too_wide;
  Balls value;  ///< 3×1, ascending: the k-th ball contains the k-th smallest eigenvalue
  long bits = 0;
};

/// exp S.
CertifiedMatrix exp(const Mat3& S, const Options& options = {});
/// exp S by arb_mat_exp at `bits` bits (an independent method; wide radii for large ‖S‖).
CertifiedMatrix exp_taylor(const Mat3& S, long bits = 256);
/// The eigenvalues of S, ascending. All three balls share one radius η (Weyl).
CertifiedEigenvalues eigenvalues(const Mat3& S, const Options& options = {});
/// S^t for symmetric positive definite S.
CertifiedMatrix pow_spd(const Mat3& S, double t, const Options& options = {});
/// The principal logarithm of symmetric positive definite S.
CertifiedMatrix log_spd(const Mat3& S, const Options& options = {});

/// ‖X − F‖_F / ‖F‖_F for a double result X against a certified F, as a ball ({+∞, 0} when X has a
/// non-finite entry; NaN mid when ‖F‖_F may be 0). A caller certifies "the error of X is e" when the
/// radius is small against it, e.g. error.rad ≤ 10⁻³ · error.mid (see certifies()).
Ball relative_error(const Mat3& X, const Balls& F);
/// ‖X − F‖_F (absolute), as a ball; for results near or below the smallest normal double.
Ball absolute_error(const Mat3& X, const Balls& F);
/// max_i |x_i − λ_i| / max(1, max_i |λ_i|) for ascending eigenvalues x (the project's eigenvalue error).
Ball eigenvalue_error(const Vec3& x, const Balls& lambda);
/// Whether a ball pins its value down to within `factor` of itself: rad ≤ factor · mid.
inline bool certifies(const Ball& error, double factor = 1e-3) { return error.rad <= factor * error.mid; }

}  // namespace affinterp::certified
