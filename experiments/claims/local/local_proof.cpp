#include "experiments/claims/local/local_proof.hpp"

#include <stdexcept>

namespace affinterp::claims::local {

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
  // The literal levels take QEPCAD far longer than the lemma chain's, and longer still on a loaded machine:
  // `affinterp prove` gives every sentence 300 s of CPU; the checks only read the stored answers.
  const proofs::DeciderLimits limits{.seconds = 300};
  std::vector<ProofSentence> sentences;
  for (const proofs::Sentence& s : plan.sentences) {
    proofs::SentenceDecision decision = proofs::decide_sentence(s, ctx.proof_files(), limits);
    sentences.push_back(proofs::to_proof_sentence(s, decision));
    run.decisions.emplace(s.name, std::move(decision));
  }
  run.proof = proofs::make_proof(plan.scope, plan.method, std::move(sentences));
  run.proof.cites = plan.cites;
  proofs::add_formulations(run.proof, plan.formulations, plan.attempts, ctx.proof_files(), limits);
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
      if (s.result == "non-empty") non_empty += (non_empty.empty() ? "" : ", ") + s.name;
    for (const Proof& formulation : run.proof.formulations)
      for (const ProofSentence& s : formulation.sentences)
        if (s.result == "non-empty") non_empty += (non_empty.empty() ? "" : ", ") + s.name;
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
