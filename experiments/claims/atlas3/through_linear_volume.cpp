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

}  // namespace affinterp::claims::atlas3
