#include "experiments/claims/sym3/certified_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace affinterp::claims::sym3 {

CertifiedTruth certified_truth(const Mat3& S) {
  const certified::CertifiedEigenvalues lambda = certified::eigenvalues(S);
  return {certified::exp(S), std::max(std::abs(lambda.value.mid(0)), std::abs(lambda.value.mid(2)))};
}

std::string_view to_string(Judgement j) {
  switch (j) {
    case Judgement::certified:
      return "certified";
    case Judgement::non_finite:
      return "non-finite where exp S is finite";
    case Judgement::finite_where_overflow:
      return "finite where exp S overflows";
    case Judgement::overflow_agreed:
      return "overflows, as exp S does";
    case Judgement::error_not_certified:
      return "error not certified (ball radius > 10⁻³ × error)";
    case Judgement::reference_too_wide:
      return "reference too wide (Arb's target not reached)";
  }
  return "?";
}

Score score(const Mat3& X, const CertifiedTruth& truth) {
  const bool finite = X.allFinite();
  switch (truth.exp.status) {
    case certified::Status::overflows:
      return {finite ? Judgement::finite_where_overflow : Judgement::overflow_agreed};
    case certified::Status::certified:
      break;
    default:
      return {Judgement::reference_too_wide};
  }
  if (!finite) return {Judgement::non_finite, INFINITY, INFINITY};
  const certified::Balls& F = truth.exp.value;
  // Ours' bound (theory/sym3/affinterp.hpp): ‖X − exp S‖_F ≤ 2·10⁻¹⁵ max(1, ‖S‖₂) ‖exp S‖_F + 2⁻¹⁰⁷².
  const double relative_bound = 2e-15 * std::max(1.0, truth.norm);
  constexpr double smallest_normal = std::numeric_limits<double>::min();  // 2⁻¹⁰²²
  // (The norm's midpoint is +∞ where ‖exp S‖_F exceeds the largest double though every entry is finite.)
  if (F.frobenius_norm().mid >= smallest_normal) {
    // Relative error as a ball (in Arb: ‖exp S‖_F may exceed the largest double).
    const certified::Ball relative = certified::relative_error(X, F);
    if (!certified::certifies(relative)) return {Judgement::error_not_certified, relative.mid, relative.upper()};
    return {Judgement::certified, relative.mid, relative.upper(),
            relative.mid / relative_bound};  // 2⁻¹⁰⁷² / ‖exp S‖_F ≤ 2⁻⁵⁰: negligible here
  }
  // exp S below the smallest normal double: the error against 2⁻¹⁰²², i.e. the relative error scaled by
  // ‖exp S‖_F / 2⁻¹⁰²². The relative error is certified at its own scale, where the double balls keep Arb's
  // radius (an absolute error there would carry the rounding of its midpoint to a subnormal double).
  const certified::Ball relative = certified::relative_error(X, F), norm = F.frobenius_norm();
  const certified::Ball absolute = certified::absolute_error(X, F);
  const bool norm_known = !std::isnan(relative.mid);  // NaN: ‖exp S‖_F may be 0
  const double error = norm_known ? relative.mid * (norm.mid / smallest_normal) : absolute.mid / smallest_normal;
  const double upper =
      norm_known ? relative.upper() * (norm.upper() / smallest_normal) : absolute.upper() / smallest_normal;
  if (!certified::certifies(norm_known ? relative : absolute)) return {Judgement::error_not_certified, error, upper};
  return {Judgement::certified, error, upper, absolute.mid / (relative_bound * norm.upper() + 0x1p-1072)};
}

}  // namespace affinterp::claims::sym3
