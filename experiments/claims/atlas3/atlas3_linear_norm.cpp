#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/citations.hpp"
#include "experiments/proofs/condition_sentences.hpp"

namespace affinterp::claims::atlas3::atlas3_linear_norm {
namespace {

using exact::Rational;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.linear.norm",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (the 3D sequel Kaji et al. announce); 3D Def 2.2.2",
    .statement = "The linear homotopy (1−t)I + tA of A ∈ GL⁺(3) is good for norm exactly when sym(A) ⪰ I or "
                 "AᵀA ⪯ sym(A): the 2D answer, word for word.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: 3D Def 2.2.2 for ((1−t)I + tA)v.
// Method: Lemma L18 — with M = A − I, P = sym M, Q = P + MᵀM, the half-derivative P(v) + t‖Mv‖² of the squared
//   norm is affine with slope ≥ 0 (L3), so good iff no v has P(v) < 0 < Q(v); by Dines' theorem on ℝ³ iff Q ⪯ 0
//   or P − νQ ⪰ 0 for some ν ≥ 0; and for each v, with p = P(v), d = ‖Mv‖² ≥ 0, p − ν(p + d) ≥ 0 forces p ≥ 0
//   (ν < 1), p + d ≤ 0 (ν > 1) or d = 0 (ν = 1, then M = 0 and P = 0): three sentences in ν, p, d. The
//   condition writes ⪰ by principal minors. QE over the nine entries of A is not attempted (LEMMAS.md, L18).
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full), where the decider's
//   certificates (goodness3.hpp) answer.

proofs::Sentence along_v(const std::string& name, const std::string& meaning, const logic::Formula& nu_range,
                         const logic::Formula& conclusion_fails) {
  using logic::Polynomial;
  const Polynomial nu = Polynomial::variable("nu"), p = Polynomial::variable("p"), d = Polynomial::variable("d");
  return proofs::sentence(
      name, meaning, {"nu", "p", "d"},
      nu_range && logic::greater_equal(d, 0) && logic::greater_equal(p - nu * (p + d), 0) && conclusion_fails);
}

atlas::AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas3_cell(proofs::Homotopy::linear, proofs::Notion::norm);
  const Polynomial nu = Polynomial::variable("nu"), p = Polynomial::variable("p"), d = Polynomial::variable("d");
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L18: no v has P(v) < 0 < Q(v) (L3) iff Q <= 0 or P - nu Q >= 0 for some nu >= 0 (Dines on "
          "R^3); along each v, with p = P(v) and d = ||Mv||^2 >= 0, p - nu(p + d) >= 0 gives p >= 0 "
          "(nu < 1), p + d <= 0 (nu > 1) or d = 0 (nu = 1): so P >= 0 or Q <= 0 or M = 0; the converse is "
          "immediate (P >= 0: every derivative starts >= 0; Q <= 0: every derivative ends <= 0)",
      .sentences = {along_v("L18.nu-below-one", "0 <= nu < 1 and p - nu(p + d) >= 0, d >= 0, with p < 0",
                            logic::greater_equal(nu, 0) && logic::less(nu, 1), logic::less(p, 0)),
                    along_v("L18.nu-above-one", "nu > 1 and p - nu(p + d) >= 0, d >= 0, with p + d > 0",
                            logic::greater(nu, 1), logic::greater(p + d, 0)),
                    along_v("L18.nu-one", "nu = 1 and p - nu(p + d) >= 0, d >= 0, with d > 0", logic::equal(nu, 1),
                            logic::greater(d, 0))},
      .cites = std::string(proofs::citations::dines_and_principal_minors),
  };
}

Outcome check(const ClaimContext& ctx) {
  logic::Point fixed;
  for (const std::string& v : {"a12", "a13", "a21", "a23", "a31", "a32"}) fixed[v] = Rational(1, 4);
  fixed["a12"] = Rational(-1, 4);
  fixed["a33"] = Rational(3, 2);
  return atlas::atlas_outcome(ctx, proofs::atlas3_cell(proofs::Homotopy::linear, proofs::Notion::norm), proof(),
                              {{"a11", "a22", -1, 3, fixed, "a33 = 3/2, a12 = -1/4, other entries 1/4"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_linear_norm
