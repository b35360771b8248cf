#include "experiments/claims/atlas3/singular_values.hpp"

#include "experiments/proofs/condition_sentences.hpp"

#include <stdexcept>

namespace affinterp::claims::atlas3 {

using logic::Formula;
using logic::Polynomial;

namespace {

Polynomial named(const char* name) { return Polynomial::variable(name); }

std::vector<proofs::AtlasCell> make_singular_value_cells() {
  const Formula positive =
      logic::greater(named("l1"), 0) && logic::greater(named("l2"), 0) && logic::greater(named("l3"), 0);
  std::vector<proofs::AtlasCell> cells;
  for (const proofs::Homotopy h : {proofs::Homotopy::svd, proofs::Homotopy::polar, proofs::Homotopy::exp_log})
    cells.push_back(
        {h,
         proofs::Notion::singular_values,
         {"l1", "l2", "l3"},
         {},
         positive,
         "l1, l2, l3 > 0 the eigenvalues of S (the singular values of A)",
         "true",
         h == proofs::Homotopy::exp_log ? "always: sigma_k(t) = l_(k)^t" : "always: sigma_k(t) = 1 + t(l_(k) - 1)",
         3});
  return cells;
}

}  // namespace

const proofs::AtlasCell& singular_values_cell(proofs::Homotopy h) {
  static const std::vector<proofs::AtlasCell> cells = make_singular_value_cells();
  for (const proofs::AtlasCell& c : cells)
    if (c.homotopy == h) return c;
  throw std::invalid_argument("no singular-value cell for the linear homotopy (it is open)");
}

std::vector<proofs::Sentence> blend_order_sentences() {
  const Polynomial a = named("a"), b = named("b"), t = named("t"), one(1);
  return {proofs::sentence("L25.blend-not-positive", "an eigenvalue a > 0 whose blend 1 + t(a - 1) is <= 0 on [0, 1]",
                           {"a", "t"},
                           logic::greater(a, 0) && logic::greater_equal(t, 0) && logic::less_equal(t, 1) &&
                               logic::less_equal(one + t * (a - one), 0)),
          proofs::sentence("L25.blend-order-changes",
                           "eigenvalues a > b > 0 whose blends swap order at some t in (0, 1]", {"a", "b", "t"},
                           logic::greater(b, 0) && logic::greater(a, b) && logic::greater(t, 0) &&
                               logic::less_equal(t, 1) && logic::less_equal(one + t * (a - one), one + t * (b - one)))};
}

std::vector<proofs::Sentence> exponent_order_sentences() {
  const Polynomial La = named("La"), Lb = named("Lb"), t = named("t");
  return {proofs::sentence(
      "L25.exponent-order-changes", "logarithms La > Lb whose multiples t La <= t Lb at some t in (0, 1]",
      {"La", "Lb", "t"},
      logic::greater(La, Lb) && logic::greater(t, 0) && logic::less_equal(t, 1) && logic::less_equal(t * La, t * Lb))};
}

Outcome blend_singular_values_outcome(const ClaimContext& ctx, proofs::Homotopy homotopy) {
  const proofs::AtlasCell& cell = singular_values_cell(homotopy);
  const atlas::AtlasProof proof{
      .scope = cell.domain_words,
      .method =
          "Lemma L25: the sorted singular values of A(t) are 1 + t(l_(k) − 1), each monotone; the residue sentences "
          "(positivity and order on (0, 1]) are empty",
      .sentences = blend_order_sentences(),
  };
  return atlas::atlas_outcome(ctx, cell, proof, {{"l1", "l2", 0, 3, {{"l3", exact::Rational(1, 2)}}, "l3 = 1/2"}});
}

}  // namespace affinterp::claims::atlas3
