#include "experiments/proofs/goodness3_formulas.hpp"

#include "experiments/proofs/goodness_formulas.hpp"

namespace affinterp::proofs {

using logic::Formula;
using logic::Polynomial;

Polynomial det_of_diagonal_blend(const Eigenvalues& l, const Polynomial& t) {
  Polynomial p(1);
  for (const Polynomial& li : l) p *= Polynomial(1) + t * (li - 1);
  return p;
}

Polynomial det_by_invariants(const Polynomial& c1, const Polynomial& c2, const Polynomial& c3, const Polynomial& t) {
  return Polynomial(1) + c1 * t + c2 * t * t + c3 * t * t * t;
}

Formula volume_property(const Polynomial& p) {
  return for_all_times("t", logic::greater(p, 0)) && monotone_derivative(p, "t");
}

Formula polar_norm_property(const Eigenvalues& l) {
  const Polynomial t = var("t");
  Polynomial q;  // ‖((1−t)I + t diag(l))v‖² = Σ (1 + t(l_i − 1))² v_i²
  for (int i = 0; i < 3; ++i) {
    const Polynomial vi = var("v" + std::to_string(i + 1)), scale = Polynomial(1) + t * (l[i] - 1);
    q += scale * scale * vi * vi;
  }
  return logic::forall({"v1", "v2", "v3"}, monotone_endpoints(q, "t"));
}

Formula cone_property(const std::array<Polynomial, 3>& sign_at_0,
                      const std::array<std::array<Polynomial, 3>, 3>& cross) {
  Formula none = logic::truth(true);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j)
        none = none &&
               !(logic::greater(sign_at_0[i], 0) && logic::less(sign_at_0[j], 0) && logic::greater(cross[i][j], 0));
  return none;
}

Formula polar_norm_cone_property(const Eigenvalues& l) {
  std::array<Polynomial, 3> at0, at1;
  for (int i = 0; i < 3; ++i) {
    at0[i] = l[i] - 1;
    at1[i] = (l[i] - 1) * l[i];
  }
  std::array<std::array<Polynomial, 3>, 3> cross;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cross[i][j] = at0[i] * at1[j] - at0[j] * at1[i];
  return cone_property(at0, cross);
}

Formula exp_log_norm_property(const Eigenvalues& l) {
  std::array<Polynomial, 3> sign;
  for (int i = 0; i < 3; ++i) sign[i] = l[i] - 1;
  std::array<std::array<Polynomial, 3>, 3> cross;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cross[i][j] = sign[i] * sign[j] * (l[j] * l[j] - l[i] * l[i]);
  return cone_property(sign, cross);
}

Formula cone_lemma_fails() {
  std::array<Polynomial, 3> a, b;
  Polynomial sum_a, sum_b;
  Formula hypotheses = logic::truth(true);
  for (int i = 0; i < 3; ++i) {
    const std::string k = std::to_string(i + 1);
    a[i] = var("a" + k);
    b[i] = var("b" + k);
    const Polynomial w = var("w" + k);
    hypotheses = hypotheses && logic::greater_equal(w, 0) &&
                 (logic::greater(a[i] * b[i], 0) || (logic::equal(a[i], 0) && logic::equal(b[i], 0)));
    sum_a += w * a[i];
    sum_b += w * b[i];
  }
  std::array<std::array<Polynomial, 3>, 3> cross;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cross[i][j] = a[i] * b[j] - a[j] * b[i];
  return hypotheses && logic::less(sum_a, 0) && logic::greater(sum_b, 0) && cone_property(a, cross);
}

}  // namespace affinterp::proofs
