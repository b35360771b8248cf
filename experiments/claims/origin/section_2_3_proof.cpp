#include "experiments/claims/origin/section_2_3_proof.hpp"

#include "experiments/proofs/ginac_polynomial.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/printed_section_2_3.hpp"
#include "theory/origin/symbols.hpp"

#include <sstream>

namespace affinterp::claims::section_2_3 {
namespace {

std::string name_of(const GiNaC::ex& symbol) {
  std::ostringstream out;
  out << symbol;
  return out.str();
}

/// v1x … v4x, then v1y … v4y.
std::vector<GiNaC::symbol> unknowns_by_coordinate() {
  const origin::Symbols& s = origin::symbols();
  std::vector<GiNaC::symbol> order;
  for (unsigned row = 0; row < 2; ++row)
    for (unsigned k = 0; k < 4; ++k) order.push_back(GiNaC::ex_to<GiNaC::symbol>(s.v(row, k)));
  return order;
}

}  // namespace

GiNaC::exmap printed_minimiser() {
  GiNaC::exmap values;
  for (const GiNaC::ex& relation : origin::printed::minimiser()) values[relation.lhs()] = relation.rhs();
  return values;
}

std::vector<proofs::Identity> stationarity_identities() {
  const GiNaC::ex& E2 = origin::thesis_study().E2_common;
  const GiNaC::exmap at_printed = printed_minimiser();
  std::vector<proofs::Identity> identities;
  for (const GiNaC::ex& u : origin::symbols().unknowns) {
    const std::string name = name_of(u);
    // Two steps the checkers perform, one identity each: the derivative, stated equal to its expanded form (affine
    // in v), then the substitution into that form; substituting into the derivative of E2 as built multiplies the
    // printed denominator once per term and made the grid's degree bound near 160 in x and y.
    const GiNaC::ex gradient = GiNaC::diff(E2, GiNaC::ex_to<GiNaC::symbol>(u)).expand();
    identities.push_back({"gradient-" + name, "∂E2(o, o)/∂" + name + " expanded (affine in v)",
                          proofs::derivative(E2, GiNaC::ex_to<GiNaC::symbol>(u)), gradient});
    identities.push_back({"stationary-" + name, "∂E2(o, o)/∂" + name + " = 0 at the printed minimiser",
                          proofs::substitution(gradient, at_printed), GiNaC::ex(0)});
  }
  return identities;
}

GiNaC::matrix hessian_by_coordinate() {
  const GiNaC::ex& E2 = origin::thesis_study().E2_common;
  const std::vector<GiNaC::symbol> order = unknowns_by_coordinate();
  GiNaC::matrix H(8, 8);
  for (unsigned i = 0; i < 8; ++i)
    for (unsigned j = 0; j < 8; ++j) H(i, j) = GiNaC::diff(GiNaC::diff(E2, order[i]), order[j]);
  return H;
}

proofs::Identity hessian_blocks_identity() {
  // The second derivatives as steps the checkers perform: ∂²E2/∂u_i∂u_j in the x block against the same in the
  // y block, and the derivatives mixing an x and a y coordinate against 0.
  const GiNaC::ex& E2 = origin::thesis_study().E2_common;
  const std::vector<GiNaC::symbol> order = unknowns_by_coordinate();
  const auto H = [&](unsigned i, unsigned j) { return proofs::derivative(proofs::derivative(E2, order[i]), order[j]); };
  GiNaC::matrix lhs(48, 1), rhs(48, 1);  // 16 entries of the x block, then the 32 mixed ones
  unsigned k = 0;
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 0; j < 4; ++j, ++k) lhs(k, 0) = H(i, j), rhs(k, 0) = H(i + 4, j + 4);
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 4; j < 8; ++j, k += 2) lhs(k, 0) = H(i, j), lhs(k + 1, 0) = H(j, i);  // rhs: 0
  return {"hessian-blocks",
          "the Hessian of E2(o, o) in (v1x … v4x, v1y … v4y) is diag(H_x, H_x): the x block equals the y block, "
          "the mixed second derivatives vanish",
          lhs, rhs};
}

proofs::Sentence hessian_sentence() {
  const GiNaC::matrix H = hessian_by_coordinate();
  std::vector<logic::Formula> some_minor_not_positive;
  for (unsigned n = 1; n <= 4; ++n) {
    GiNaC::matrix leading(n, n);
    for (unsigned i = 0; i < n; ++i)
      for (unsigned j = 0; j < n; ++j) leading(i, j) = H(i, j);
    some_minor_not_positive.push_back(logic::less_equal(proofs::to_polynomial(leading.determinant().expand()), 0));
  }
  return {"hessian-not-positive-definite",
          "some origin where a leading principal minor of H_x is ≤ 0 (E2 not strictly convex in v)",
          logic::exists({"x", "y"}, logic::disjunction(std::move(some_minor_not_positive))),
          {}};
}

proofs::Sentence denominator_sentence() {
  const logic::Polynomial D = proofs::to_polynomial(GiNaC::denom(origin::printed::min_E2()).expand());
  return {"denominator-not-positive",
          "some origin where x² + 2xy + y² − 2x − 2y + 3 ≤ 0",
          logic::exists({"x", "y"}, logic::less_equal(D, 0)),
          {}};
}

}  // namespace affinterp::claims::section_2_3
