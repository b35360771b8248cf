#include "experiments/proofs/goodness_formulas.hpp"

#include <stdexcept>

namespace affinterp::proofs {

using logic::greater;
using logic::greater_equal;
using logic::less;
using logic::less_equal;

Polynomial var(const std::string& name) { return Polynomial::variable(name); }

Polynomial det(const PolyMat2& W) { return W[0][0] * W[1][1] - W[0][1] * W[1][0]; }

Polynomial trace(const PolyMat2& W) { return W[0][0] + W[1][1]; }

PolyMat2 product(const PolyMat2& A, const PolyMat2& B) {
  PolyMat2 C;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j];
  return C;
}

PolyMat2 transpose(const PolyMat2& A) { return {{{A[0][0], A[1][0]}, {A[0][1], A[1][1]}}}; }

PolyMat2 rotation(const Polynomial& c, const Polynomial& s) { return {{{c, -s}, {s, c}}}; }

PolyMat2 blend(const PolyMat2& B, const Polynomial& t) {
  const Polynomial s = Polynomial(1) - t;
  return {{{s + t * B[0][0], t * B[0][1]}, {t * B[1][0], s + t * B[1][1]}}};
}

Polynomial det_of_blend(const PolyMat2& B, const std::string& t) { return det(blend(B, var(t))); }

Polynomial norm_squared_of_blend(const PolyMat2& B, const Polynomial& v1, const Polynomial& v2, const std::string& t) {
  const PolyMat2 A = blend(B, var(t));
  const Polynomial w1 = A[0][0] * v1 + A[0][1] * v2, w2 = A[1][0] * v1 + A[1][1] * v2;
  return w1 * w1 + w2 * w2;
}

Formula on_unit_interval(const Polynomial& t) { return greater_equal(t, 0) && less_equal(t, 1); }

Formula for_all_times(const std::string& t, const Formula& body) {
  return logic::forall({t}, logic::implies(on_unit_interval(var(t)), body));
}

Formula positive_semidefinite(const PolyMat2& W) {
  return greater_equal(W[0][0], 0) && greater_equal(W[1][1], 0) && greater_equal(det(W), 0);
}

Formula monotone_literal(const Polynomial& f, const std::string& t) {
  const std::string s1 = t + "s", t1 = t + "t";  // fresh names: s1 ≤ t1 in [0, 1]
  const Polynomial fs = f.substitute(t, var(s1)), ft = f.substitute(t, var(t1));
  const Formula ordered = greater_equal(var(s1), 0) && less_equal(var(s1), var(t1)) && less_equal(var(t1), 1);
  return logic::forall({s1, t1}, logic::implies(ordered, less_equal(fs, ft))) ||
         logic::forall({s1, t1}, logic::implies(ordered, greater_equal(fs, ft)));
}

Formula monotone_derivative(const Polynomial& f, const std::string& t) {
  const Polynomial df = f.derivative(t);
  return for_all_times(t, greater_equal(df, 0)) || for_all_times(t, less_equal(df, 0));
}

Formula monotone_endpoints(const Polynomial& f, const std::string& t) {
  const Polynomial df = f.derivative(t), slope0 = df.substitute(t, 0), slope1 = df.substitute(t, 1);
  return !(less(slope0, 0) && greater(slope1, 0)) && !(greater(slope0, 0) && less(slope1, 0));
}

Formula area_property(const PolyMat2& B, const std::string& level) {
  const Polynomial f = det_of_blend(B, "t");
  if (level == "L") return for_all_times("t", greater(f, 0)) && monotone_literal(f, "t");
  if (level == "D") return for_all_times("t", greater(f, 0)) && monotone_derivative(f, "t");
  if (level == "E") {
    // Lemma L2 applies to f = 1 + c1 t + c2 t².
    if (f.degree_in("t") > 2 || !(f.substitute("t", 0) == Polynomial(1)))
      throw std::logic_error("area_property level E: det((1-t)I + tB) is not 1 + c1 t + c2 t^2");
    return greater(f.substitute("t", 1), 0) && monotone_endpoints(f, "t");
  }
  throw std::invalid_argument("area_property: no level " + level);
}

Formula norm_property(const PolyMat2& B, const std::string& level) {
  const Polynomial v1 = var("v1"), v2 = var("v2");
  const Formula unit = logic::equal(v1 * v1 + v2 * v2, 1);
  const Polynomial q = norm_squared_of_blend(B, v1, v2, "t");
  if (level == "L") return logic::forall({"v1", "v2"}, logic::implies(unit, monotone_literal(q, "t")));
  if (level == "D") return logic::forall({"v1", "v2"}, logic::implies(unit, monotone_derivative(q, "t")));
  if (level == "E") {
    // Lemma L3: ½ q′ = P(v) + t‖Mv‖² is affine with slope ≥ 0.
    if (q.degree_in("t") > 2) throw std::logic_error("norm_property level E: ||A(t)v||^2 is not quadratic in t");
    return logic::forall({"v1", "v2"}, logic::implies(unit, monotone_endpoints(q, "t")));
  }
  if (level == "N") {
    PolyMat2 M = B;
    M[0][0] -= Polynomial(1);
    M[1][1] -= Polynomial(1);
    const Polynomial half(exact::Rational(1, 2)), nu = var("nu");
    const PolyMat2 MtM = product(transpose(M), M);
    PolyMat2 minus_Q, W;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const Polynomial P = half * (M[i][j] + M[j][i]), Q = P + MtM[i][j];
        minus_Q[i][j] = -Q;
        W[i][j] = P - nu * Q;
      }
    return positive_semidefinite(minus_Q) || logic::exists({"nu"}, greater_equal(nu, 0) && positive_semidefinite(W));
  }
  throw std::invalid_argument("norm_property: no level " + level);
}

Formula norm_property_directions(const PolyMat2& B, const std::string& level) {
  const auto monotone = [&](const Polynomial& f) {
    if (level == "L") return monotone_literal(f, "t");
    if (level == "D") return monotone_derivative(f, "t");
    if (level == "E") {
      // Lemma L2 (b) reads f′ at t = 0 and 1 when it is affine.
      if (f.degree_in("t") > 2) throw std::logic_error("norm_property_directions level E: not quadratic in t");
      return monotone_endpoints(f, "t");
    }
    throw std::invalid_argument("norm_property_directions: no level " + level);
  };
  const Polynomial zero(0), one(1);
  return logic::forall({"m"}, monotone(norm_squared_of_blend(B, one, var("m"), "t"))) &&
         monotone(norm_squared_of_blend(B, zero, one, "t"));
}

Polynomial svd_norm_G(const Polynomial& x, const Polynomial& y, const Polynomial& beta, const Polynomial& t) {
  const Polynomial one(1), two(2), four(4);
  return four * (x - one) * (y - one) * (one + t * (x - one)) * (one + t * (y - one)) -
         beta * beta * t * t * pow(x - y, 2) * pow(two + t * (x + y - two), 2);
}

Formula svd_norm_property(const Polynomial& x, const Polynomial& y, const Polynomial& beta) {
  return for_all_times("t", greater_equal(svd_norm_G(x, y, beta, var("t")), 0));
}

}  // namespace affinterp::proofs
