#include "experiments/proofs/goodness_levels.hpp"

namespace affinterp::proofs {

namespace {

using logic::Formula;
using logic::Polynomial;

Polynomial det(const PolyMat2& W) { return W[0][0] * W[1][1] - W[0][1] * W[1][0]; }
Polynomial trace(const PolyMat2& W) { return W[0][0] + W[1][1]; }

/// W ⪰ 0 for symmetric W: both diagonal entries and the determinant ≥ 0.
Formula positive_semidefinite(const PolyMat2& W) {
  return logic::greater_equal(W[0][0], 0) && logic::greater_equal(W[1][1], 0) && logic::greater_equal(det(W), 0);
}

Formula on_unit_interval(const Polynomial& t) { return logic::greater_equal(t, 0) && logic::less_equal(t, 1); }

}  // namespace

Formula area_level_D(const PolyMat2& B, const std::string& t_name) {
  const Polynomial t = Polynomial::variable(t_name), s = Polynomial(1) - t;
  const PolyMat2 blend{{{s + t * B[0][0], t * B[0][1]}, {t * B[1][0], s + t * B[1][1]}}};
  const Polynomial f = det(blend), df = f.derivative(t_name);
  const auto all_t = [&](const Formula& f) { return logic::forall({t_name}, logic::implies(on_unit_interval(t), f)); };
  return all_t(logic::greater(f, 0)) && (all_t(logic::greater_equal(df, 0)) || all_t(logic::less_equal(df, 0)));
}

Formula area_level_E(const PolyMat2& B) {
  // det((1−t)I + tB) = 1 + t(tr B − 2) + t²(1 − tr B + det B): derivative tr B − 2 at 0, 2 det B − tr B at 1.
  const Polynomial slope0 = trace(B) - Polynomial(2), slope1 = Polynomial(2) * det(B) - trace(B);
  return logic::greater(det(B), 0) && !(logic::less(slope0, 0) && logic::greater(slope1, 0)) &&
         !(logic::greater(slope0, 0) && logic::less(slope1, 0));
}

Formula norm_level_N(const PolyMat2& B, const std::string& nu_name) {
  const Polynomial nu = Polynomial::variable(nu_name), half(exact::Rational(1, 2));
  PolyMat2 M = B;
  M[0][0] -= Polynomial(1);
  M[1][1] -= Polynomial(1);
  PolyMat2 P, Q, minus_Q, W;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      P[i][j] = half * (M[i][j] + M[j][i]);
      Q[i][j] = P[i][j] + M[0][i] * M[0][j] + M[1][i] * M[1][j];  // (MᵀM)_ij
    }
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      minus_Q[i][j] = -Q[i][j];
      W[i][j] = P[i][j] - nu * Q[i][j];
    }
  return positive_semidefinite(minus_Q) ||
         logic::exists({nu_name}, logic::greater_equal(nu, 0) && positive_semidefinite(W));
}

}  // namespace affinterp::proofs
