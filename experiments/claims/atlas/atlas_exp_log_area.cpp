#include "experiments/claims/atlas/proved_cell.hpp"
#include "experiments/claims/claim.hpp"
#include "experiments/proofs/citations.hpp"

namespace affinterp::claims::atlas::atlas_exp_log_area {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas.exp-log.area",
    .chapter = Chapter::atlas,
    .where = "beyond the papers (the goodness atlas); Def 2.2.1, Kaji §3",
    .statement = "The exp-log homotopy R_{tθ} S^t, S positive definite, is good for area for every S.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: Def 2.2.1 for det A_E(t) = det S^t.
// Method: Lemma L10 — S = Q diag(λ1, λ2) Qᵀ, S^t = Q diag(λ1^t, λ2^t) Qᵀ, so det A_E(t) = (λ1λ2)^t =
//   e^{t log det S}: positive, with derivative log(det S)·(det S)^t of one sign; so good for area iff det S > 0.
//   The algebraic residue is one sentence (a point of the domain with det S ≤ 0); "¬condition ∧ property" is
//   empty because the condition is `true`.
// Sizes: the sentence is the same at every size; the suite has no exact decider for this cell.

AtlasProof proof() {
  using logic::Polynomial;
  const proofs::AtlasCell& cell = proofs::atlas_cell(proofs::Homotopy::exp_log, proofs::Notion::area);
  return AtlasProof{
      .scope = cell.domain_words,
      .method =
          "Lemma L10 (exp-log): det A(t) = (det S)^t = exp(t log det S), positive with a derivative of one "
          "sign, so good for area iff det S > 0; the residue sentence (det S <= 0 on the domain) is empty, "
          "and condition-false-property-true is empty because the condition is true",
      .sentences = {atlas_sentence(cell, "cond-not-prop.residue",
                                   "a positive definite S with det S <= 0 (where L10's reduced property fails)",
                                   !logic::greater(cell.macros.at("det"), 0))},
      .z3_only = {},
      .identities = {},
      .cites = std::string(proofs::citations::exponential),
      .formulations = {},
      .attempts = {{.formulation = "Def 2.2.1 as written for R_{t theta} S^t",
                    .sentences = {},
                    .not_expressible = std::string(proofs::not_first_order_exponential)}},
  };
}

Outcome check(const ClaimContext& ctx) {
  return atlas_outcome(ctx, proofs::atlas_cell(proofs::Homotopy::exp_log, proofs::Notion::area), proof(),
                       {{"x", "y", 0, 4, {{"h", Rational(1, 2)}}, "h = 1/2"}});
}

}  // namespace
}  // namespace affinterp::claims::atlas::atlas_exp_log_area
