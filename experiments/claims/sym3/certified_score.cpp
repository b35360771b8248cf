#include "experiments/claims/sym3/certified_score.hpp"

#include <algorithm>
#include <cmath>

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
  const certified::Ball relative = certified::relative_error(X, truth.exp.value);
  if (!certified::certifies(relative)) return {Judgement::error_not_certified, relative.mid, relative.upper()};
  // Ours' bound (theory/sym3/affinterp.hpp): 2·10⁻¹⁵ max(1, ‖S‖₂) ‖exp S‖_F + 2⁻¹⁰⁷².
  const certified::Ball absolute = certified::absolute_error(X, truth.exp.value);
  const double bound = 2e-15 * std::max(1.0, truth.norm) * truth.exp.value.frobenius_norm().lower() + 0x1p-1072;
  return {Judgement::certified, relative.mid, relative.upper(), absolute.mid / bound};
}

}  // namespace affinterp::claims::sym3
