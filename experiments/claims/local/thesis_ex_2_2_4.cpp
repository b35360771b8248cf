#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "plots/local/figures.hpp"
#include "theory/local/affine_map.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/quadratic_field.hpp"
#include "theory/local/svd_norm_goodness.hpp"

namespace affinterp::claims::local::thesis_ex_2_2_4 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.ex-2.2.4",
    .chapter = Chapter::local,
    .where = "thesis §2.2.4",
    .statement = "The worked example's A, its SVD R_{π/3} diag(2,1) R_{−5π/3} and polar form R_{−4π/3} S are correct; "
                 "linear interpolation is good for neither area nor norm, SVD for area, polar for both.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: the printed angles lie outside the stated ranges (β = −5π/3 outside [0, 2π), the polar angle −4π/3
//   outside Kaji's (−π, π]); the matrices are what is claimed, and the evidence notes the angles.
// Method: everything exact in ℚ(√3), where cos and sin of multiples of π/3 lie: eq. (1) for the triangle pair, the
//   printed SVD and polar decomposition, and the four goodness statements by the exact deciders of Defs 2.2.1 and
//   2.2.2. Draws thesis Figs 2.2–2.5. Proof for all reals: the same statements as sentences in r3 with r3² = 3, r3 > 0
//   (so r3 = √3), decided by QEPCAD B and Z3: the decompositions and eq. (1) at once, and each goodness statement
//   at level D (area, Lemma L1) or E (norm, Lemmas L3, L4); under the full size also SVD area at level L. Beyond
//   the thesis: the SVD interpolation of diag(2, 1) is good for norm for no β ≠ 0 (Lemma L9).
// Sizes: one example at either size; the full size adds the level-L sentence.

using affinterp::local::det2;
using affinterp::local::exactly_equal;
using affinterp::local::good_for_area;
using affinterp::local::good_for_norm;
using affinterp::local::Mat2;
using affinterp::local::QSqrt3;
using exact::Rational;

QSqrt3 q(Rational a, Rational b = 0) { return QSqrt3(std::move(a), std::move(b)); }

/// R_{kπ/3} exactly.
Mat2<QSqrt3> rotation_pi_thirds(int k) {
  static const QSqrt3 cosines[6] = {q(1),  q(Rational(1) / 2),  q(Rational(-1) / 2),
                                    q(-1), q(Rational(-1) / 2), q(Rational(1) / 2)};
  static const QSqrt3 sines[6] = {q(0), q(0, Rational(1) / 2),  q(0, Rational(1) / 2),
                                  q(0), q(0, Rational(-1) / 2), q(0, Rational(-1) / 2)};
  const int i = ((k % 6) + 6) % 6;
  Mat2<QSqrt3> R;
  R << cosines[i], -sines[i], sines[i], cosines[i];
  return R;
}

Mat2<QSqrt3> product(const Mat2<QSqrt3>& a, const Mat2<QSqrt3>& b) { return a.lazyProduct(b); }

/// The example as printed: the triangles P, Q of eq. (1), A, the SVD's D and the polar factor S.
struct PrintedExample {
  affinterp::local::Triangle<QSqrt3> P, Q;
  Mat2<QSqrt3> A, D, S;
};

PrintedExample printed_example() {
  PrintedExample e;
  e.P << q(0), q(0), q(2), q(0), q(3), q(0);  // p1 = (0,0), p2 = (0,3), p3 = (2,0)
  e.Q << q(0), q(0, Rational(-9) / 4), q(Rational(-1) / 2), q(0), q(Rational(-15) / 4), q(0, Rational(3) / 2);
  e.A << q(Rational(-1) / 4), q(0, Rational(-3) / 4), q(0, Rational(3) / 4), q(Rational(-5) / 4);
  e.D << q(2), q(0), q(0), q(1);
  e.S << q(Rational(5) / 4), q(0, Rational(-1) / 4), q(0, Rational(-1) / 4), q(Rational(7) / 4);
  return e;
}

nlohmann::json surd_matrix(const Mat2<QSqrt3>& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 2; ++i) rows.push_back({to_string(M(i, 0)), to_string(M(i, 1))});
  return rows;
}

/// a + b√3 as the polynomial a + b·r3.
Polynomial in_r3(const QSqrt3& u) { return Polynomial(u.a) + Polynomial(u.b) * var("r3"); }

PolyMat2 in_r3(const Mat2<QSqrt3>& M) { return {{{in_r3(M(0, 0)), in_r3(M(0, 1))}, {in_r3(M(1, 0)), in_r3(M(1, 1))}}}; }

/// Some entry of X − Y is not 0.
Formula differ(const PolyMat2& X, const PolyMat2& Y) {
  std::vector<Formula> parts;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) parts.push_back(logic::not_equal(X[i][j], Y[i][j]));
  return logic::disjunction(std::move(parts));
}

/// A sentence in r3 = √3 (r3² = 3, r3 > 0, so Q(√3)'s entries are polynomials in r3), empty iff `f` never holds.
proofs::Sentence in_sqrt3(std::string name, std::string meaning, const Formula& f) {
  const Polynomial r3 = var("r3");
  return sentence(std::move(name), std::move(meaning), {"r3"}, logic::equal(r3 * r3, 3) && logic::greater(r3, 0) && f);
}

/// The thesis's statements straight from Defs 2.2.1 and 2.2.2 (level L, unit v), Lemma
/// L4 decided; `decompositions` and `svd_not_good_area_L` are the plan's sentences of the same statements.
proofs::FormulationPlan as_written(const PolyMat2& A, const PolyMat2& S, const proofs::Sentence& decompositions,
                                   const proofs::Sentence& svd_not_good_area_L) {
  return {
      "Defs 2.2.1 and 2.2.2 as written (level L) for every statement of the thesis: det A(t) > 0 for every t in "
      "[0, 1] and monotone for all 0 <= s <= t <= 1; ||A(t)v|| monotone for all 0 <= s <= t <= 1 and every unit "
      "v, through its square (Lemma L4, a sentence); the rotations have det 1 and are orthogonal (Lemma L5, "
      "identities). No other lemma",
      {lemma_L4(), decompositions,
       in_sqrt3("linear-good-area.L", "the linear interpolation of A is good for area (level L)",
                area_property(A, "L")),
       in_sqrt3("linear-good-norm.L", "the linear interpolation of A is good for norm (level L)",
                norm_property(A, "L")),
       svd_not_good_area_L,
       in_sqrt3("polar-not-good-area.L", "the polar interpolation (S) is not good for area (level L)",
                !area_property(S, "L")),
       in_sqrt3("polar-not-good-norm.L", "the polar interpolation (S) is not good for norm (level L)",
                !norm_property(S, "L"))}};
}

/// The proof: every statement of the example as an existential sentence in r3 = √3 that is empty iff it holds.
ProofPlan proof_plan() {
  const auto [P, Q, A_printed, D_printed, S_printed] = printed_example();
  const PolyMat2 A = in_r3(A_printed), D = in_r3(D_printed), S = in_r3(S_printed);
  using affinterp::claims::local::product;  // of polynomial matrices
  const PolyMat2 svd = product(product(in_r3(rotation_pi_thirds(1)), D), in_r3(rotation_pi_thirds(-5)));
  const PolyMat2 polar = product(in_r3(rotation_pi_thirds(-4)), S);
  // Eq. (1): A p_j + d = q_j with d = 0, i.e. A P = Q column by column.
  std::vector<Formula> eq1;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 2; ++i)
      eq1.push_back(logic::not_equal(A[i][0] * in_r3(P(0, j)) + A[i][1] * in_r3(P(1, j)), in_r3(Q(i, j))));
  const Formula S_positive = logic::greater(S[0][0], 0) && logic::greater(det(S), 0);
  ProofPlan plan{
      "the worked example: r3 = sqrt 3 (r3^2 = 3, r3 > 0); entries in Q(sqrt 3)",
      "every statement as an existential sentence in r3 that is empty iff it holds: the decompositions and eq. (1) "
      "by their entries; Def 2.2.1 at level D (Lemma L1) for det((1-t)I + tB), B = A, D, S (Lemma L5: the "
      "rotations have det 1); Def 2.2.2 at level E (Lemmas L3, L4) for ((1-t)I + tB)v, B = A, S; beyond the "
      "thesis, the SVD interpolation of D = diag(2, 1) at level G (Lemma L9) for beta != 0; SVD area also at level L "
      "(Def 2.2.1 as written)",
      {in_sqrt3("decompositions-wrong",
                "R_{pi/3} D R_{-5pi/3} != A, R_{-4pi/3} S != A, S not positive definite, or A P != Q (eq. (1))",
                differ(svd, A) || differ(polar, A) || !S_positive || logic::disjunction(eq1)),
       in_sqrt3("linear-good-area", "the linear interpolation of A is good for area", area_property(A, "D")),
       in_sqrt3("linear-good-norm", "the linear interpolation of A is good for norm", norm_property(A, "E")),
       in_sqrt3("svd-not-good-area", "the SVD interpolation (D = diag(2, 1)) is not good for area",
                !area_property(D, "D")),
       in_sqrt3("polar-not-good-area", "the polar interpolation (S) is not good for area", !area_property(S, "D")),
       in_sqrt3("polar-not-good-norm", "the polar interpolation (S) is not good for norm", !norm_property(S, "E")),
       sentence("svd-good-norm-some-beta",
                "beyond the thesis: some beta != 0 makes the SVD interpolation of diag(2, 1) good for norm", {"beta"},
                logic::not_equal(var("beta"), 0) && svd_norm_property(Polynomial(2), Polynomial(1), var("beta")))},
      {}};
  plan.sentences.push_back(in_sqrt3("svd-not-good-area.L", "the same at level L", !area_property(D, "L")));
  plan.formulations.push_back(as_written(A, S, plan.sentences.front(), plan.sentences.back()));
  // Def 2.2.2 for the SVD homotopy as written is no sentence for a decider.
  plan.attempts.push_back(
      {.formulation = "beyond the thesis, svd-good-norm-some-beta as written (Def 2.2.2 for R_{t alpha}((1-t)I + "
                      "tD)R_{t beta})",
       .sentences = {},
       .not_expressible = std::string(proofs::not_first_order_rotation)});
  return plan;
}

Outcome check(const ClaimContext& ctx) {
  const auto [P, Q, A_printed, D, S_printed] = printed_example();

  const auto map = affinterp::local::affine_map(P, Q);
  const bool A_right =
      exactly_equal(map.A, A_printed) && exactly_equal(map.d, affinterp::local::Vec2<QSqrt3>(q(0), q(0)));
  const bool svd_right = exactly_equal(product(product(rotation_pi_thirds(1), D), rotation_pi_thirds(-5)),
                                       A_printed);  // R_{π/3} D R_{−5π/3}
  const bool polar_right = exactly_equal(product(rotation_pi_thirds(-4), S_printed), A_printed) &&
                           S_printed(0, 0) > q(0) && det2(S_printed) > q(0);
  // Kaji's Appendix: S = R_{−β} D R_β with β = −5π/3.
  const bool appendix_consistent =
      exactly_equal(product(product(rotation_pi_thirds(5), D), rotation_pi_thirds(-5)), S_printed);

  const bool linear_area = good_for_area(A_printed), linear_norm = good_for_norm(A_printed);
  const bool svd_area = good_for_area(D), polar_area = good_for_area(S_printed), polar_norm = good_for_norm(S_printed);
  // Not stated in the thesis: the SVD interpolation's norm behaviour, with the printed β and its principal value.
  const bool svd_norm_printed_beta = affinterp::local::svd_good_for_norm_at_pi_multiple(2, 1, Rational(-5) / 3);
  const bool svd_norm_principal_beta = affinterp::local::svd_good_for_norm_at_pi_multiple(2, 1, Rational(1) / 3);

  const bool statements_hold = !linear_area && !linear_norm && svd_area && polar_area && polar_norm;
  Outcome outcome;
  outcome.evidence.method = "exact arithmetic in Q(sqrt 3); goodness by the exact deciders of Defs 2.2.1/2.2.2";
  outcome.evidence.sample_size = 1;
  outcome.evidence.details = {
      {"A_from_eq1", surd_matrix(map.A)},
      {"A_printed_matches_eq1", A_right},
      {"svd_R(pi/3) diag(2,1) R(-5pi/3) == A", svd_right},
      {"polar_R(-4pi/3) S == A, S positive definite", polar_right},
      {"S == R(-beta) D R(beta) (Kaji Appendix)", appendix_consistent},
      {"linear_good_for_area", linear_area},
      {"linear_good_for_norm", linear_norm},
      {"svd_good_for_area", svd_area},
      {"polar_good_for_area", polar_area},
      {"polar_good_for_norm", polar_norm},
      {"svd_good_for_norm (not stated; Lemmas L9 + L12) with beta = -5pi/3", svd_norm_printed_beta},
      {"svd_good_for_norm (not stated; Lemmas L9 + L12) with beta = pi/3", svd_norm_principal_beta},
      {"angle_conventions",
       "beta = -5pi/3 lies outside the thesis's own range [0, 2pi) (same matrix as pi/3); the polar angle "
       "-4pi/3 = alpha + beta lies outside Kaji's branch (-pi, pi] (principal value 2pi/3). The matrices are "
       "right; the interpolation paths A_s(t), A_p(t) depend on which representative is used."},
      {"caption_note",
       "Figure 2.5's caption says det A_s(t) for the linear interpolation; the plotted function is det A_l(t)"}};
  const bool decompositions_right = A_right && svd_right && polar_right;
  outcome.verdict = decompositions_right && statements_hold ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = outcome.verdict == Verdict::confirmed
                        ? "A, its SVD R_{pi/3} diag(2,1) R_{-5pi/3} and polar form R_{-4pi/3} S are exact in Q(sqrt "
                          "3); linear is good for "
                          "neither area nor norm, SVD is good for area, polar for area and norm (printed angles lie "
                          "outside the stated ranges)"
                        : "the example's matrices or goodness statements do not all hold";
  attach_proof(outcome, run_proof(ctx, proof_plan()));
  if (ctx.draws_figures()) outcome.figures = ctx.figure_refs(plots::draw_thesis_figures_2_2_to_2_5(ctx.figure_dir));
  if (outcome.verdict == Verdict::refuted)
    outcome.counterexample = {
        {"A", surd_matrix(A_printed)}, {"S", surd_matrix(S_printed)}, {"details", outcome.evidence.details}};
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_ex_2_2_4
