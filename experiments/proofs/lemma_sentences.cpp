#include "experiments/proofs/lemma_sentences.hpp"

#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/goodness_formulas.hpp"

namespace affinterp::proofs {

namespace {

using logic::greater;
using logic::greater_equal;
using logic::less;
using logic::less_equal;

/// f = 1 + c1 t + c2 t², every quadratic with f(0) = 1 (det((1−t)I + tB) is one).
Polynomial generic_quadratic() { return Polynomial(1) + var("c1") * var("t") + var("c2") * var("t") * var("t"); }

Formula differ(const Formula& a, const Formula& b) { return (a && !b) || (!a && b); }

}  // namespace

Sentence lemma_L1() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L1.literal-vs-derivative",
                  "Lemma L1 fails for some quadratic f = 1 + c1 t + c2 t^2: monotone on [0, 1] as written (for all "
                  "s <= t) differs from f' >= 0 or f' <= 0 on [0, 1]",
                  {"c1", "c2"}, differ(monotone_literal(f, "t"), monotone_derivative(f, "t")));
}

Sentence lemma_L2() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L2.derivative-vs-endpoint",
                  "Lemma L2 fails for some f = 1 + c1 t + c2 t^2: f' (affine) of one sign on [0, 1] differs from its "
                  "values at t = 0 and 1 not of opposite strict signs",
                  {"c1", "c2"}, differ(monotone_derivative(f, "t"), monotone_endpoints(f, "t")));
}

Sentence lemma_L2_area() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L2.area-positivity",
                  "Lemma L2 fails for some f = 1 + c1 t + c2 t^2: (f > 0 on [0, 1] and monotone) differs from (f(1) > "
                  "0 and endpoint-monotone)",
                  {"c1", "c2"},
                  differ(for_all_times("t", greater(f, 0)) && monotone_derivative(f, "t"),
                         greater(f.substitute("t", 1), 0) && monotone_endpoints(f, "t")));
}

Sentence lemma_L3() {
  const Polynomial g0 = var("g0"), slope = var("sl"), ta = var("ta"), tb = var("tb");
  const Formula both_signs = logic::exists({"ta", "tb"}, on_unit_interval(ta) && on_unit_interval(tb) &&
                                                             less(g0 + slope * ta, 0) && greater(g0 + slope * tb, 0));
  return sentence(
      "lemma.L3.affine-sign-change",
      "Lemma L3 fails for some affine g = g0 + sl t with slope sl >= 0: g takes both strict signs on [0, 1] "
      "differs from g(0) < 0 < g(1)",
      {"g0", "sl"}, greater_equal(slope, 0) && differ(both_signs, less(g0, 0) && greater(g0 + slope, 0)));
}

Sentence lemma_L4() {
  const Polynomial a = var("a"), b = var("b");
  return sentence("lemma.L4.norm-vs-square",
                  "Lemma L4 fails for some a, b >= 0 (two norms): a <= b differs from a^2 <= b^2", {"a", "b"},
                  greater_equal(a, 0) && greater_equal(b, 0) && differ(less_equal(a, b), less_equal(a * a, b * b)));
}

Sentence lemma_L6_directions() {
  const Polynomial v1 = var("v1"), v2 = var("v2"), l = var("l"), m = var("m");
  const Formula multiple_of_1_m =
      logic::exists({"l", "m"}, logic::not_equal(l, 0) && logic::equal(v1, l) && logic::equal(v2, l * m));
  const Formula multiple_of_0_1 =
      logic::exists({"l"}, logic::not_equal(l, 0) && logic::equal(v1, 0) && logic::equal(v2, l));
  return sentence("lemma.L6.directions",
                  "Lemma L6 fails: a unit vector v that is neither l(1, m) nor l(0, 1) for any real m and l != 0",
                  {"v1", "v2"}, logic::equal(v1 * v1 + v2 * v2, 1) && !multiple_of_1_m && !multiple_of_0_1);
}

Sentence lemma_L7_normal_form() {
  const PolyMat2 A{{{var("a"), var("b")}, {var("c"), var("d")}}}, O = rotation(var("co"), var("si"));
  const PolyMat2 conjugated = product(product(transpose(O), A), O);
  const Formula unit = logic::equal(var("co") * var("co") + var("si") * var("si"), 1);
  return sentence(
      "lemma.L7.normal-form", "Lemma L7 fails: a real 2x2 A such that no rotation O makes sym(O^T A O) diagonal",
      {"a", "b", "c", "d"},
      logic::forall({"co", "si"}, logic::implies(unit, logic::not_equal(conjugated[0][1] + conjugated[1][0], 0))));
}

}  // namespace affinterp::proofs
