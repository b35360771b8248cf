#include "experiments/claims/local/local_proof.hpp"

#include <stdexcept>

namespace affinterp::claims::local {

using logic::greater;
using logic::less;
using proofs::for_all_times;
using proofs::monotone_derivative;
using proofs::monotone_endpoints;
using proofs::monotone_literal;
using proofs::on_unit_interval;

namespace {

/// f = 1 + c1 t + c2 t², every quadratic with f(0) = 1 (det((1−t)I + tB) is one).
Polynomial generic_quadratic() { return Polynomial(1) + var("c1") * var("t") + var("c2") * var("t") * var("t"); }

Formula differ(const Formula& a, const Formula& b) { return (a && !b) || (!a && b); }

}  // namespace

proofs::Sentence lemma_L1() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L1.literal-vs-derivative",
                  "Lemma L1 fails for some quadratic f = 1 + c1 t + c2 t^2: monotone on [0, 1] as written (for all "
                  "s <= t) differs from f' >= 0 or f' <= 0 on [0, 1]",
                  {"c1", "c2"}, differ(monotone_literal(f, "t"), monotone_derivative(f, "t")));
}

proofs::Sentence lemma_L2() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L2.derivative-vs-endpoint",
                  "Lemma L2 fails for some f = 1 + c1 t + c2 t^2: f' (affine) of one sign on [0, 1] differs from its "
                  "values at t = 0 and 1 not of opposite strict signs",
                  {"c1", "c2"}, differ(monotone_derivative(f, "t"), monotone_endpoints(f, "t")));
}

proofs::Sentence lemma_L2_area() {
  const Polynomial f = generic_quadratic();
  return sentence("lemma.L2.area-positivity",
                  "Lemma L2 fails for some f = 1 + c1 t + c2 t^2: (f > 0 on [0, 1] and monotone) differs from (f(1) > "
                  "0 and endpoint-monotone)",
                  {"c1", "c2"},
                  differ(for_all_times("t", greater(f, 0)) && monotone_derivative(f, "t"),
                         greater(f.substitute("t", 1), 0) && monotone_endpoints(f, "t")));
}

proofs::Sentence lemma_L3() {
  const Polynomial g0 = var("g0"), slope = var("sl"), ta = var("ta"), tb = var("tb");
  const Formula both_signs = logic::exists({"ta", "tb"}, on_unit_interval(ta) && on_unit_interval(tb) &&
                                                             less(g0 + slope * ta, 0) && greater(g0 + slope * tb, 0));
  return sentence(
      "lemma.L3.affine-sign-change",
      "Lemma L3 fails for some affine g = g0 + sl t with slope sl >= 0: g takes both strict signs on [0, 1] "
      "differs from g(0) < 0 < g(1)",
      {"g0", "sl"}, logic::greater_equal(slope, 0) && differ(both_signs, less(g0, 0) && greater(g0 + slope, 0)));
}

std::string ProofRun::result(const std::string& name) const {
  for (const ProofSentence& s : proof.sentences)
    if (s.name == name) return s.result;
  throw std::out_of_range("no sentence " + name + " in the proof");
}

ProofRun run_proof(const ClaimContext& ctx, const ProofPlan& plan) {
  ProofRun run;
  run.identities = nlohmann::json::object();
  for (const auto& [name, difference] : plan.identities) {
    if (!difference.is_zero()) throw std::logic_error("identity " + name + " fails: " + to_string(difference));
    run.identities[name] = "zero polynomial (exact arithmetic)";
  }
  // The literal levels take QEPCAD up to ~45 s of CPU (140 s measured at load 14): `affinterp prove` gives every
  // sentence 300 s; the checks only read the stored answers.
  const proofs::DeciderLimits limits{.seconds = 300};
  std::vector<ProofSentence> sentences;
  for (const proofs::Sentence& s : plan.sentences) {
    proofs::SentenceDecision decision = proofs::decide_sentence(s, ctx.proof_files(), limits);
    sentences.push_back(proofs::to_proof_sentence(s, decision));
    run.decisions.emplace(s.name, std::move(decision));
  }
  run.proof = proofs::make_proof(plan.scope, plan.method, std::move(sentences));
  run.proof.cites = plan.cites;
  return run;
}

std::optional<logic::Point> counterexample(const ProofRun& run, const std::string& name, const proofs::Predicate& exact,
                                           const std::vector<logic::Point>& simple_points) {
  const auto it = run.decisions.find(name);
  if (it == run.decisions.end() || it->second.result != proofs::SetResult::non_empty) return std::nullopt;
  if (it->second.witness) return proofs::shrink_witness(it->second.witness->point, exact, simple_points);
  // QEPCAD prints no sample point for a sentence with a universal block, and Z3 may print none either.
  for (const logic::Point& p : simple_points)
    if (exact(p)) return proofs::shrink_witness(p, exact, simple_points);
  return std::nullopt;
}

nlohmann::json exact_point(const logic::Point& p) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : p) out[name] = exact::to_string(value);
  return out;
}

void attach_proof(Outcome& outcome, ProofRun run) {
  if (const std::optional<Strength> strength = proof_strength(run.proof);
      outcome.verdict == Verdict::confirmed && strength) {
    // The proof decides for all reals: a non-empty sentence contradicts the grid's "confirmed".
    std::string non_empty;
    for (const ProofSentence& s : run.proof.sentences)
      if (s.result != "empty") non_empty += (non_empty.empty() ? "" : ", ") + s.name;
    if (!non_empty.empty())
      throw std::runtime_error("the proof for all reals contradicts the verdict confirmed: non-empty " + non_empty);
    outcome.strength = *strength;
  }
  outcome.evidence.details["proof_identities"] = run.identities;
  outcome.proof = std::move(run.proof);
}

void require_agreement(const Outcome& outcome, const std::optional<Verdict>& proved) {
  if (proved && *proved != outcome.verdict)
    throw std::runtime_error("the proof for all reals reaches " + std::string(to_string(*proved)) + ", the grid " +
                             std::string(to_string(outcome.verdict)));
}

}  // namespace affinterp::claims::local
