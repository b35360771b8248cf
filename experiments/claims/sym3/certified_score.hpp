#pragma once
// One double exponential judged against its Arb-certified truth (theory/certified/sym3.hpp), the way the
// accuracy claim and its peer table count it: an error counts only where its ball certifies it
// (radius ≤ 10⁻³ · error, certified::certifies); everything else is a stated exclusion or a failure.
#include "theory/certified/sym3.hpp"

#include <string_view>

namespace affinterp::claims::sym3 {

using certified::Mat3;

/// What the certified truth is for one S (computed once, shared by every algorithm).
struct CertifiedTruth {
  certified::CertifiedMatrix exp;  ///< exp S as balls; status certified, overflows or too_wide
  double norm = 0;                 ///< ‖S‖₂ = max |λ| (certified eigenvalues' midpoints)
};

CertifiedTruth certified_truth(const Mat3& S);

enum class Judgement {
  certified,              ///< exp S finite, result finite, its relative error certified (`error`)
  non_finite,             ///< exp S finite, the result has a NaN or ∞ entry: wrong
  finite_where_overflow,  ///< exp S overflows in double, the result is finite: wrong
  overflow_agreed,        ///< exp S overflows and so does the result: right, no error figure
  error_not_certified,    ///< excluded: the error's ball is wider than 10⁻³ of it (`error_upper` bounds it)
  reference_too_wide,     ///< excluded: Arb did not reach its target or could not decide overflow
};

std::string_view to_string(Judgement j);

struct Score {
  Judgement judgement = Judgement::reference_too_wide;
  /// The certified error ‖X − exp S‖_F / max(‖exp S‖_F, 2⁻¹⁰²²) (mid): the relative Frobenius error, measured
  /// against the smallest normal double where exp S lies below it (there double results are only resolved
  /// to 2⁻¹⁰⁷⁴, so a relative error would call every algorithm wrong).
  double error = 0;
  double error_upper = 0;  ///< its rigorous upper bound (for error_not_certified too)
  /// The certified absolute error over ours' bound 2·10⁻¹⁵ max(1, ‖S‖₂) ‖exp S‖_F + 2⁻¹⁰⁷²
  /// (theory/sym3/affinterp.hpp); 0 unless judgement == certified.
  double over_own_bound = 0;
};

/// The judgement of a double result X for exp S.
Score score(const Mat3& X, const CertifiedTruth& truth);

}  // namespace affinterp::claims::sym3
