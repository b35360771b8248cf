#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/goodness_formulas.hpp"

namespace affinterp::claims::atlas::atlas_svd_norm {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.svd.norm",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.2, thesis Thm 2.2.3 (exact at β = 0)",
    .statement = "The SVD homotopy R_{tα}((1−t)I + tD)R_{tβ}, D = diag(x, y), x, y > 0, β the right rotation's "
                 "angle in radians, is good for norm exactly when β²(x − y)²(x + y)² ≤ 4xy(x − 1)(y − 1).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.2 for ‖A_s(t)v‖; R_{tα} is orthogonal (Lemma L5) but R_{tβ} on the right is not removable.
// Method: Lemma L9 (by hand, reports/proofs/LEMMAS.md): with G(t) = 4(x−1)(y−1)(1 + t(x−1))(1 + t(y−1))
//   − β²t²(x−y)²(2 + t(x+y−2))², good for norm ⇔ G(t) ≥ 0 for all t ∈ [0, 1]; the condition is G(1) ≥ 0.
//   Property ⇒ condition is the instance t = 1 (one sentence). Condition ⇒ property (Lemma L12, worst time
//   t = 1) in σ = x + y − 2, π = (x−1)(y−1), B = β² (an identity turns G into these): Z3 decides it directly
//   ("cond-not-prop.sym"), where QEPCAD exhausts its prime list; QEPCAD decides it through L12's chain instead:
//   G is affine in B with slope ≤ 0; at the largest admissible B* = 4π(1+σ+π)/((σ²−4π)(2+σ)²), G equals
//   4π(1−t)C/(2+σ)² (identity) with C ≥ 0 on [0, 1]; the cases π < 0, π = 0 and x = y separately. Every chain
//   sentence is decided by both deciders.
// Sizes: the sentences are the same at every size. No second line against theory/local: its exact SVD-norm
//   decider (svd_norm_goodness.hpp) is this very condition, so comparing them could not fail.

using logic::Formula;
using logic::Polynomial;
using proofs::on_unit_interval;
using proofs::sentence;

Polynomial named(const char* name) { return Polynomial::variable(name); }

/// L9's G(t) in the symmetric coordinates σ (sg), π (pi) and B = β², at time tt, B = b and π = p.
Polynomial Gs(const Polynomial& tt, const Polynomial& b, const Polynomial& p) {
  const Polynomial sg = named("sg"), one(1), two(2), four(4);
  return four * p * (one + tt * sg + tt * tt * p) - b * tt * tt * (sg * sg - four * p) * pow(two + tt * sg, 2);
}

/// L12's C(σ, π, t), with (1 − t)C = (1 + tσ + t²π)(2 + σ)² − t²(2 + tσ)²(1 + σ + π).
Polynomial C_of_L12() {
  const Polynomial sg = named("sg"), pi = named("pi"), t = named("t"), one(1), four(4);
  return pow(sg, 3) * (t * t * t + t * t + t) + sg * sg * pi * (t * t * t + t * t) +
         sg * sg * (t * t * t + Polynomial(5) * t * t + Polynomial(5) * t + one) + four * sg * pi * t * t +
         four * sg * (t * t + Polynomial(2) * t + one) + four * t + four;
}

/// Lemma L12's chain (condition ⇒ property through the worst time t = 1), each sentence empty iff its step holds:
/// G's slope in B is ≤ 0, C ≥ 0 on [0, 1], and the degenerate cases π < 0, π = 0 and x = y.
std::vector<proofs::Sentence> l12_chain() {
  const Polynomial B = named("B"), pi = named("pi"), sg = named("sg"), t = named("t"), one(1), two(2), four(4);
  const Formula symmetric_domain = logic::greater_equal(B, 0) && logic::greater_equal(sg * sg - four * pi, 0) &&
                                   logic::greater(one + sg + pi, 0) && logic::greater(sg + two, 0);
  return {
      sentence("L12.slope-in-B-positive", "G's slope in B, -t^2 (sg^2 - 4 pi)(2 + t sg)^2, positive somewhere",
               {"sg", "pi", "t"},
               logic::greater_equal(sg * sg - four * pi, 0) && on_unit_interval(t) &&
                   logic::greater(-(t * t) * (sg * sg - four * pi) * pow(two + t * sg, 2), 0)),
      sentence("L12.C-negative", "C < 0 somewhere on [0, 1] with pi > 0, sg^2 > 4 pi, x, y > 0", {"sg", "pi", "t"},
               logic::greater(sg * sg - four * pi, 0) && logic::greater(one + sg + pi, 0) &&
                   logic::greater(sg + two, 0) && logic::greater(pi, 0) && on_unit_interval(t) &&
                   logic::less(C_of_L12(), 0)),
      sentence("L12.degenerate.pi-negative", "pi < 0 (x, y on opposite sides of 1) with the condition true",
               {"B", "sg", "pi"}, symmetric_domain && logic::less(pi, 0) && logic::greater_equal(Gs(one, B, pi), 0)),
      sentence("L12.degenerate.pi-zero", "pi = 0 (x = 1 or y = 1): G(1) >= 0 but G(t) < 0 for some t", {"B", "sg", "t"},
               logic::greater_equal(B, 0) && logic::greater(one + sg, 0) && logic::greater(sg + two, 0) &&
                   logic::greater_equal(Gs(one, B, Polynomial(0)), 0) && on_unit_interval(t) &&
                   logic::less(Gs(t, B, Polynomial(0)), 0)),
      sentence("L12.degenerate.x-equals-y", "sg^2 = 4 pi (x = y): G(t) < 0 for some t", {"B", "sg", "t"},
               logic::greater_equal(B, 0) && logic::greater(sg + two, 0) && on_unit_interval(t) &&
                   logic::less(Gs(t, B, Polynomial(exact::Rational(1, 4)) * sg * sg), 0))};
}

/// The identities the method rests on (each lhs − rhs must be the zero polynomial): the condition is G(1), G in
/// the symmetric coordinates, L12's C, and G at the largest admissible B* (Lemma L12).
std::vector<std::pair<std::string, Polynomial>> identities() {
  const Polynomial x = named("x"), y = named("y"), beta = named("beta"), t = named("t"), one(1), two(2), four(4);
  const Polynomial pi = named("pi"), sg = named("sg"), C = C_of_L12();
  const auto G = [&](const Polynomial& tt) { return proofs::svd_norm_G(x, y, beta, tt); };
  const Polynomial N = four * pi * (one + sg + pi), D = (sg * sg - four * pi) * pow(two + sg, 2);
  const Polynomial G_at_Bstar_times_D =
      four * pi * (one + t * sg + t * t * pi) * D - N * t * t * (sg * sg - four * pi) * pow(two + t * sg, 2);
  const Polynomial svd_coordinates = Gs(t, named("B"), pi)
                                         .substitute("sg", x + y - two)
                                         .substitute("pi", (x - one) * (y - one))
                                         .substitute("B", beta * beta);
  return {{"condition-is-G(1): 4xy(x-1)(y-1) - beta^2(x-y)^2(x+y)^2 = G(1)",
           four * x * y * (x - one) * (y - one) - beta * beta * pow(x - y, 2) * pow(x + y, 2) - G(one)},
          {"svd-coordinates: G(t) in x, y, beta = G(t) in sg, pi, B", G(t) - svd_coordinates},
          {"L12.C: (1-t)C = (1+t sg+t^2 pi)(2+sg)^2 - t^2(2+t sg)^2(1+sg+pi)",
           (one - t) * C -
               ((one + t * sg + t * t * pi) * pow(two + sg, 2) - t * t * pow(two + t * sg, 2) * (one + sg + pi))},
          {"L12.G-at-B*: D G(t)|B=N/D = 4 pi (1-t) C (sg^2 - 4 pi), N = 4 pi (1+sg+pi), D = (sg^2-4pi)(2+sg)^2",
           G_at_Bstar_times_D - four * pi * (one - t) * C * (sg * sg - four * pi)}};
}

AtlasProof proof() {
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::svd, proofs::Notion::norm);
  const Polynomial x = named("x"), y = named("y"), beta = named("beta"), t = named("t"), one(1), two(2), four(4);
  const Polynomial B = named("B"), pi = named("pi"), sg = named("sg");
  const Formula symmetric_domain = logic::greater_equal(B, 0) && logic::greater_equal(sg * sg - four * pi, 0) &&
                                   logic::greater(one + sg + pi, 0) && logic::greater(sg + two, 0);
  std::vector<proofs::Sentence> sentences = {
      atlas_sentence(cell, "prop-not-cond.inst",
                     "x, y, beta where G(1) >= 0 (the property's instance t = 1) and the condition fails",
                     !cell.condition_formula() && logic::greater_equal(proofs::svd_norm_G(x, y, beta, one), 0)),
      sentence("cond-not-prop.sym",
               "sg, pi, B of some x, y > 0, beta where G(1) >= 0 but G(t) < 0 for some t in [0, 1]",
               {"B", "pi", "sg", "t"},
               symmetric_domain && logic::greater_equal(Gs(one, B, pi), 0) && on_unit_interval(t) &&
                   logic::less(Gs(t, B, pi), 0))};
  for (proofs::Sentence& step : l12_chain()) sentences.push_back(std::move(step));
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L9 (by hand, reports/proofs/LEMMAS.md): good for norm iff G(t) = 4(x-1)(y-1)(1+t(x-1))(1+t(y-1)) - "
          "beta^2 t^2 (x-y)^2 (2+t(x+y-2))^2 >= 0 for all t in [0, 1]; the condition is G(1) >= 0 (identity). Property "
          "=> condition: "
          "the instance t = 1 (prop-not-cond.inst). Condition => property (Lemma L12, worst time t = 1), in "
          "sg = x+y-2, pi = (x-1)(y-1), B = beta^2 (identity): decided directly by Z3 (cond-not-prop.sym; QEPCAD "
          "exhausts its prime list there), and by both deciders through L12's chain: G is affine in B with slope "
          "<= 0 (L12.slope-in-B-positive), at the largest admissible B* it equals 4 pi (1-t) C/(2+sg)^2 "
          "(identities) with C >= 0 on [0, 1] (L12.C-negative), and the cases pi < 0, pi = 0, x = y "
          "(L12.degenerate.*)",
      .sentences = std::move(sentences),
      .z3_only = {"cond-not-prop.sym"},
      .identities = identities(),
      .attempts = {{.formulation = "Def 2.2.2 as written for R_{t alpha}((1-t)I + tD)R_{t beta}",
                    .sentences = {},
                    .not_expressible = std::string(proofs::not_first_order_rotation)}},
  };
}

Outcome check(const ClaimContext& ctx) {
  std::vector<Slice> slices;
  for (const auto& [b, label] : std::vector<std::pair<Rational, std::string>>{
           {0, "beta = 0"}, {Rational(1, 2), "beta = 1/2"}, {1, "beta = 1"}, {2, "beta = 2"}})
    slices.push_back({"x", "y", 0, 3, {{"beta", b}}, label});
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::svd, proofs::Notion::norm), proof(), slices);
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_svd_norm
