#include "experiments/proofs/formulation.hpp"

#include <algorithm>

namespace affinterp::proofs {

namespace {

Attempt attempt_of(const std::string& words, const ProofSentence& sentence, const ProofSentence::Run& run) {
  return {words,
          sentence.name,
          run.tool,
          run.file,
          run.cpu_seconds,
          run.max_rss_kb,
          run.result == "unknown" ? (run.reason.empty() ? "unknown" : run.reason) : run.result};
}

}  // namespace

Proof decide_formulation(const std::string& scope, const FormulationPlan& plan, const SentenceFiles& files,
                         const DeciderLimits& limits) {
  std::vector<ProofSentence> sentences;
  for (const Sentence& s : plan.sentences) sentences.push_back(prove_sentence(s, files, limits));
  return make_proof(scope, plan.method, std::move(sentences));
}

std::vector<Attempt> decide_attempt(const AttemptPlan& plan, const SentenceFiles& files) {
  if (plan.sentences.empty()) return {{plan.formulation, "", "", "", {}, {}, plan.not_expressible}};
  std::vector<Attempt> attempts;
  for (const Sentence& s : plan.sentences) {
    const ProofSentence decided = to_proof_sentence(s, decide_sentence(s, files, plan.limits));
    for (const ProofSentence::Run& run : decided.runs) attempts.push_back(attempt_of(plan.formulation, decided, run));
  }
  return attempts;
}

std::vector<Attempt> unanswered_runs(const Proof& proof, const std::string& words) {
  std::vector<Attempt> attempts;
  for (const ProofSentence& s : proof.sentences)
    for (const ProofSentence::Run& run : s.runs)
      if (run.result == "unknown") attempts.push_back(attempt_of(words, s, run));
  return attempts;
}

void add_formulations(Proof& proof, const std::vector<FormulationPlan>& formulations,
                      const std::vector<AttemptPlan>& attempts, const SentenceFiles& files,
                      const DeciderLimits& limits) {
  // A lemma shared by two formulations is one run: recorded once, under the first.
  const auto recorded = [&](const Attempt& a) {
    return std::any_of(proof.attempts.begin(), proof.attempts.end(),
                       [&](const Attempt& b) { return b.sentence == a.sentence && b.tool == a.tool; });
  };
  for (const FormulationPlan& plan : formulations) {
    proof.formulations.push_back(decide_formulation(proof.scope, plan, files, limits));
    for (Attempt& a : unanswered_runs(proof.formulations.back(), plan.method))
      if (!recorded(a)) proof.attempts.push_back(std::move(a));
  }
  for (const AttemptPlan& plan : attempts)
    for (Attempt& a : decide_attempt(plan, files)) proof.attempts.push_back(std::move(a));
}

}  // namespace affinterp::proofs
