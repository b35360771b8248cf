#include "experiments/claims/local/area_theorem_proof.hpp"

#include "experiments/claims/local/area_witness.hpp"
#include "experiments/claims/local/printed_conditions.hpp"
#include "experiments/claims/values.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

namespace affinterp::claims::local {

ProofPlan area_theorem_plan(const AreaParameters& p) {
  const Polynomial tr = trace(p.B), dt = det(p.B), t = var("t");
  const Formula printed = thm_2_2_1_formula(tr, dt), corrected = corrected_area_formula(tr, dt);
  ProofPlan plan;
  plan.scope = p.scope;
  plan.method =
      "Def 2.2.1 for det A(t) = det((1-t)I + tB) = 1 + (tr B - 2)t + (1 - tr B + det B)t^2 (identity)" +
      (p.rotations.empty() ? std::string() : "; " + p.rotations) +
      ". Level E: positive and monotone on [0, 1] iff det B > 0 and the derivative's values tr B - 2 (t = 0) and "
      "2 det B - tr B (t = 1) are not of opposite strict signs (Lemmas L1, L2; L2 decided as its own sentences for "
      "every quadratic 1 + c1 t + c2 t^2). Printed condition and its correction each against the property: "
      "cond-not-prop and prop-not-cond empty = equivalent. Second formulations: level D (derivative, Lemma L1, decided "
      "as its own sentence) and level L "
      "(Def 2.2.1 as written, for all 0 <= s <= t <= 1).";
  plan.sentences = {lemma_L2(), lemma_L2_area(), lemma_L1()};
  const std::vector<std::string> levels{"E", "D", "L"};
  for (const std::string& level : levels) {
    const Formula good = area_property(p.B, level);
    for (const auto& [base, condition] : {std::pair{"printed.", printed}, std::pair{"corrected.", corrected}}) {
      plan.sentences.push_back(cond_not_prop(base, level, p.variables, p.domain, condition, good));
      plan.sentences.push_back(prop_not_cond(base, level, p.variables, p.domain, condition, good));
    }
  }
  const Polynomial quadratic = Polynomial(1) + (tr - Polynomial(2)) * t + (Polynomial(1) - tr + dt) * t * t;
  plan.identities = {
      {"det((1-t)I + tB) = 1 + (tr B - 2)t + (1 - tr B + det B)t^2", det_of_blend(p.B, "t") - quadratic}};
  return plan;
}

std::optional<Verdict> area_proof_verdict(const ProofRun& run) {
  if (!run.decided()) return std::nullopt;
  const auto empty = [&](const std::string& name) { return run.result(name) == "empty"; };
  if (empty("printed.cond-not-prop.E") && empty("printed.prop-not-cond.E")) return Verdict::confirmed;
  if (empty("corrected.cond-not-prop.E") && empty("corrected.prop-not-cond.E")) return Verdict::corrected;
  return Verdict::refuted;
}

nlohmann::json area_proof_counterexample(const ProofRun& run, const AreaParameters& p) {
  using affinterp::local::det2;
  const auto fails = [&](const logic::Point& at) {
    if (!p.in_domain(at)) return false;
    const auto B = p.B_at(at);
    return affinterp::local::thm_2_2_1_condition<exact::Rational>(B.trace(), det2(B)) &&
           !affinterp::local::good_for_area(B);
  };
  const auto point = counterexample(run, "printed.cond-not-prop.E", fails);
  if (!point) return nullptr;
  const auto B = p.B_at(*point);
  return {{"point", exact_point(*point)},
          {"B", exact_matrix(B)},
          {"printed_condition", true},
          {"good_for_area (theory/local/goodness.hpp)", false},
          {"witness", area_witness(B)},
          {"found_by",
           "the deciders' sample point of printed.cond-not-prop.E, shrunk to small rationals and "
           "re-verified exactly"}};
}

}  // namespace affinterp::claims::local
