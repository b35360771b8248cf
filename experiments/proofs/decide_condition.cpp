#include "experiments/proofs/decide_condition.hpp"

#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/witness.hpp"

#include <map>
#include <stdexcept>

namespace affinterp::proofs {

namespace {

using logic::Formula;
using logic::Polynomial;

/// The sentence as the deciders get it. For the linear norm, b = s − k and c = s + k (symmetric and skew
/// parts) with the variable order (a, d, s, k): QEPCAD then finishes in seconds where it runs out of cells in
/// any order of a, b, c, d.
struct Encoding {
  Formula formula;
  std::vector<std::string> variables, qepcad_order;
  logic::Point to_cell(const logic::Point& p) const;
  bool symmetric_skew = false;
};

logic::Point Encoding::to_cell(const logic::Point& p) const {
  if (!symmetric_skew) return p;
  return {{"a", p.at("a")}, {"b", p.at("s") - p.at("k")}, {"c", p.at("s") + p.at("k")}, {"d", p.at("d")}};
}

Encoding encode(const AtlasCell& cell, const Formula& quantifier_free) {
  if (cell.dimension == 2 && cell.homotopy == Homotopy::linear && cell.notion == Notion::norm) {
    const Polynomial s = Polynomial::variable("s"), k = Polynomial::variable("k");
    const Formula f = logic::substitute(logic::substitute(quantifier_free, "b", s - k), "c", s + k);
    const std::vector<std::string> order{"a", "d", "s", "k"};
    return {logic::exists(order, f), order, order, true};
  }
  return {logic::exists(cell.variables, quantifier_free), cell.variables, {}, false};
}

/// The 3D cells' simple points: the identity map (M = 0, all eigenvalues 1) and eigenvalues at 1 one by one.
std::vector<logic::Point> simple_points3(const AtlasCell& cell) {
  if (cell.variables.front() == "c1") return {{{"c1", 0}, {"c2", 0}, {"c3", 0}}, {{"c3", 0}}, {{"c2", 0}, {"c3", 0}}};
  if (cell.variables.front() == "l1") return {{{"l1", 1}, {"l2", 1}, {"l3", 1}}, {{"l3", 1}}, {{"l2", 1}, {"l3", 1}}};
  logic::Point identity, off_diagonal_zero;
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j) {
      const std::string name = "a" + std::to_string(i) + std::to_string(j);
      identity[name] = i == j ? 1 : 0;
      if (i != j) off_diagonal_zero[name] = 0;
    }
  return {identity, off_diagonal_zero};
}

/// Simple points tried first when shrinking: the identity map and its neighbours.
std::vector<logic::Point> simple_points(const AtlasCell& cell) {
  if (cell.dimension == 3) return simple_points3(cell);
  if (cell.homotopy == Homotopy::linear) return {{{"a", 1}, {"b", 0}, {"c", 0}, {"d", 1}}, {{"b", 0}, {"c", 0}}};
  return {{{"x", 1}, {"y", 1}, {"h", 0}, {"beta", 0}}, {{"h", 0}, {"beta", 0}}, {{"beta", 1}}};
}

}  // namespace

const AtlasCell& decide_cell(int dimension, const std::string& homotopy, const std::string& notion) {
  const std::map<std::string, Homotopy> homotopies = {
      {"linear", Homotopy::linear}, {"svd", Homotopy::svd}, {"polar", Homotopy::polar}, {"exp-log", Homotopy::exp_log}};
  if (!homotopies.contains(homotopy))
    throw std::invalid_argument("homotopy '" + homotopy + "': expected linear, svd, polar or exp-log");
  const Homotopy h = homotopies.at(homotopy);
  if (dimension == 2) {
    if (notion != "area" && notion != "norm")
      throw std::invalid_argument("notion '" + notion + "': expected area or norm in 2D");
    return atlas_cell(h, notion == "area" ? Notion::area : Notion::norm);
  }
  if (dimension != 3) throw std::invalid_argument("dimension " + std::to_string(dimension) + ": expected 2 or 3");
  if (notion != "volume" && notion != "norm")
    throw std::invalid_argument("notion '" + notion + "': expected volume or norm in 3D");
  if (h == Homotopy::svd && notion == "norm")
    throw std::invalid_argument(
        "the 3D svd norm cell is open (reports/proofs/LEMMAS.md, L19): nothing to decide against");
  return atlas3_cell(h, notion == "volume" ? Notion::volume : Notion::norm);
}

std::string_view to_string(ConditionVerdict::Verdict v) {
  switch (v) {
    case ConditionVerdict::Verdict::equivalent:
      return "equivalent";
    case ConditionVerdict::Verdict::not_equivalent:
      return "not-equivalent";
    case ConditionVerdict::Verdict::unknown:
      return "unknown";
  }
  return "unknown";
}

ConditionVerdict decide_condition(const AtlasCell& cell, const Formula& condition, const DeciderLimits& limits,
                                  const SentenceFiles& files) {
  const Formula property = cell.condition_formula();
  struct Side {
    const char* name;
    bool condition;  // the condition's value on this side; the property has the other
    Formula set;
  };
  const std::vector<Side> sides = {
      {"condition-true-property-false", true, cell.domain && condition && !property},
      {"condition-false-property-true", false, cell.domain && !condition && property},
  };
  ConditionVerdict answer;
  bool all_empty = true;
  for (const Side& side : sides) {
    const Encoding e = encode(cell, side.set);
    SentenceDecision d = decide_sentence({side.name, "", e.formula, e.qepcad_order}, files, limits);
    answer.sides.push_back(d);
    if (d.disagreement) {
      answer.verdict = ConditionVerdict::Verdict::unknown;
      answer.reason = "the deciders disagree on " + d.answers();
      return answer;
    }
    all_empty = all_empty && d.result == SetResult::empty;
    if (!d.reasons().empty())  // unknown, or decided by one decider only
      answer.reason += (answer.reason.empty() ? "" : "; ") + std::string(side.name) + ": " + d.reasons();
    if (d.result != SetResult::non_empty) continue;

    answer.verdict = ConditionVerdict::Verdict::not_equivalent;
    if (!d.witness) {
      answer.reason = std::string(side.name) + " is non-empty, but no decider printed a point of it";
      return answer;
    }
    const auto holds = [&](const logic::Point& p) { return logic::holds(side.set, p); };
    const std::optional<logic::Point> point = shrink_witness(e.to_cell(d.witness->point), holds, simple_points(cell));
    if (!point) {
      answer.reason = std::string(side.name) +
                      " is non-empty; its sample point is algebraic and no rational "
                      "point near it was found";
      return answer;
    }
    Counterexample c{*point, side.condition, !side.condition, false};
    if (const std::optional<bool> good = suite_says_good(cell, *point)) {
      if (*good != c.property)
        throw std::logic_error("the atlas condition of " + cell.id() +
                               " and the suite's exact decider disagree at a counterexample");
      c.checked_by_suite = true;
    }
    answer.counterexample = c;
    answer.reason.clear();
    return answer;
  }
  if (all_empty) answer.verdict = ConditionVerdict::Verdict::equivalent;
  return answer;
}

}  // namespace affinterp::proofs
