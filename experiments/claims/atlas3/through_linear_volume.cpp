#include "experiments/claims/atlas3/through_linear_volume.hpp"

#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3 {

using logic::Polynomial;

proofs::FormulationPlan through_linear_volume(const proofs::AtlasCell& eigenvalue_cell) {
  const proofs::AtlasCell& linear = proofs::atlas3_cell(proofs::Homotopy::linear, proofs::Notion::volume);
  const Polynomial p = proofs::det_by_invariants(Polynomial::variable("c1"), Polynomial::variable("c2"),
                                                 Polynomial::variable("c3"), Polynomial::variable("t"));
  const logic::Formula property = proofs::volume_property(p);
  const auto& m = eigenvalue_cell.macros;
  return {.method =
              "through the linear cell (Lemma L16): det((1-t)I + t diag(l)) = 1 + c1 t + c2 t^2 + c3 t^3 "
              "for the invariants c of diag(l) - I (identity vieta), which lie in the linear cell's domain "
              "(sentence linear.in-domain); the linear cell's two sentences, decided here again",
          .sentences = {atlas::atlas_sentence(eigenvalue_cell, "linear.in-domain",
                                              "eigenvalues l1, l2, l3 > 0 whose c1, c2, c3 leave the linear cell's "
                                              "domain (1 + c1 + c2 + c3 <= 0)",
                                              !logic::greater(Polynomial(1) + m.at("c1") + m.at("c2") + m.at("c3"), 0)),
                        proofs::cond_not_prop("linear.", "D", linear.variables, linear.domain,
                                              linear.condition_formula(), property),
                        proofs::prop_not_cond("linear.", "D", linear.variables, linear.domain,
                                              linear.condition_formula(), property)}};
}

std::pair<std::string, Polynomial> vieta_identity(const proofs::AtlasCell& eigenvalue_cell) {
  const Polynomial t = Polynomial::variable("t");
  const proofs::Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  const auto& m = eigenvalue_cell.macros;
  return {"vieta",
          proofs::det_of_diagonal_blend(l, t) - proofs::det_by_invariants(m.at("c1"), m.at("c2"), m.at("c3"), t)};
}

namespace {

atlas::AtlasProof eigenvalue_volume_proof(const proofs::AtlasCell& cell) {
  const proofs::Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  return atlas::AtlasProof{
      .scope = cell.domain_words,
      .method =
          "3D Def 2.2.1 for det((1-t)I + t diag(l1, l2, l3)) = prod(1 + t(l_i - 1)) (the rotations have "
          "determinant 1, Lemma L14) at level D: positive on [0, 1] and the derivative of one sign there "
          "(Lemma L1)",
      .sentences = atlas::condition_sentences(
          cell, "D", proofs::volume_property(proofs::det_of_diagonal_blend(l, Polynomial::variable("t")))),
      .identities = {vieta_identity(cell)},
      .formulations = {through_linear_volume(cell)},
  };
}

}  // namespace

Outcome eigenvalue_volume_outcome(const ClaimContext& ctx, proofs::Homotopy homotopy) {
  const proofs::AtlasCell& cell = proofs::atlas3_cell(homotopy, proofs::Notion::volume);
  return atlas::atlas_outcome(ctx, cell, eigenvalue_volume_proof(cell),
                              {{"l1", "l2", 0, 4, {{"l3", exact::Rational(1, 4)}}, "l3 = 1/4"},
                               {"l1", "l2", 0, 4, {{"l3", exact::Rational(3)}}, "l3 = 3"}});
}

}  // namespace affinterp::claims::atlas3
