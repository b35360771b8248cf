#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/citations.hpp"
#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/lemma_sentences.hpp"
#include "experiments/proofs/literal_formulations.hpp"

namespace affinterp::claims::atlas::atlas_linear_norm {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.linear.norm",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.2",
    .statement = "The linear homotopy (1−t)I + tA, det A > 0, is good for norm exactly when sym(A) ⪰ I or "
                 "AᵀA ⪯ sym(A) (Loewner order, sym(A) = (A + Aᵀ)/2).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.2 for ‖((1−t)I + tA)v‖.
// Method: in a, b, c, d neither decider finishes within its limits, so first Lemma L7: conjugating A by a
//   rotation O changes neither notion ((1−t)I + tOᵀAO = Oᵀ((1−t)I + tA)O, and v ↦ Ov is a bijection of the
//   circle) nor the condition (sym and AᵀA are conjugated alike, and congruence keeps ⪰); the rotation that
//   diagonalises sym(A) brings A to [[p, −k], [k, r]] (p, r the eigenvalues of sym(A), k = (c − b)/2; the skew
//   part commutes with rotations). Then level N (Lemmas L3, L4, L6, L8) in p, r, k with ν quantified.
// Second formulations without Dines' theorem: in the normal form, the directions (1, m), (0, 1) at levels
//   D and E, each lemma a sentence (L7's rotation: lemma.L7.normal-form).
// Sizes: the sentences are the same at every size; random points 200 (quick) / 2000 (full) in a, b, c, d.

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::linear, proofs::Notion::norm);
  const Polynomial p = Polynomial::variable("p"), r = Polynomial::variable("r"), k = Polynomial::variable("k");
  const proofs::PolyMat2 normal_form{{{p, -k}, {k, r}}};
  logic::Formula condition = cell.condition_formula();
  for (const auto& [name, by] :
       std::vector<std::pair<std::string, Polynomial>>{{"a", p}, {"b", -k}, {"c", k}, {"d", r}})
    condition = logic::substitute(condition, name, by);
  const logic::Formula domain = logic::greater(p * r + k * k, 0);  // det A > 0
  const logic::Formula property = proofs::norm_property(normal_form, "N");
  // The second formulations: without Dines' theorem, over the directions (1, m), (0, 1) in the normal form; the
  // normal form's rotation decided as a sentence.
  std::vector<proofs::FormulationPlan> formulations =
      proofs::norm_directions({"conj.", {"p", "r", "k"}, domain, condition, normal_form});
  for (proofs::FormulationPlan& f : formulations) {
    f.method =
        "in the normal form [[p, -k], [k, r]] of Lemma L7 (identities; the rotation that brings A to it "
        "exists: sentence lemma.L7.normal-form): " +
        f.method;
    f.sentences.insert(f.sentences.begin(), proofs::lemma_L7_normal_form());
  }
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L7: conjugation by a rotation changes neither Def 2.2.2 nor the condition, and brings A to the "
          "normal form [[p, -k], [k, r]] (p, r the eigenvalues of sym(A), k = (c - b)/2); there, Def 2.2.2 at "
          "level N: the squared norm (L4) has an affine t-derivative with non-negative slope, so it is monotone "
          "for v unless P(v) < 0 < Q(v), P = sym(A - I), Q = P + (A - I)^T(A - I) (L3); homogeneous in v "
          "(L6); no such v iff Q <= 0 or P - nu Q >= 0 for some nu >= 0 (Dines 1941, L8)",
      .sentences = {proofs::cond_not_prop("conj.", "N", {"p", "r", "k"}, domain, condition, property),
                    proofs::prop_not_cond("conj.", "N", {"p", "r", "k"}, domain, condition, property)},
      .z3_only = {},
      .identities = {},
      .cites = std::string(proofs::citations::dines),
      .formulations = formulations,
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::linear, proofs::Notion::norm), proof(),
                       {{"a", "d", -1, 3, {{"b", Rational(1, 4)}, {"c", Rational(1, 4)}}, "b = c = 1/4"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_linear_norm
