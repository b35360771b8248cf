#include "experiments/claims/prover.hpp"

#include "experiments/claims/runner.hpp"

#include <map>
#include <ostream>
#include <set>
#include <sstream>

namespace affinterp::claims {

namespace {

/// The decider runs the claims' proofs need, one per transcript file.
std::vector<proofs::PlannedRun> collect_plan(const ClaimRegistry& registry, const ProveOptions& options) {
  proofs::ProofPlan plan;
  RunContext context;
  context.size = Size::quick;
  context.threads = options.jobs;
  context.answer_dir = options.answer_dir;
  context.plan = &plan;
  std::ostringstream ignored;  // the checks' verdicts without answers are not this command's output
  run_claims(registry, context, options.ids, ignored);
  std::map<std::filesystem::path, proofs::PlannedRun> unique;
  for (proofs::PlannedRun& run : plan.runs()) unique.insert_or_assign(run.transcript_file(), std::move(run));
  std::vector<proofs::PlannedRun> runs;
  for (auto& [file, run] : unique) runs.push_back(std::move(run));
  return runs;
}

}  // namespace

ProveSummary prove_claims(const ClaimRegistry& registry, const ProveOptions& options, std::ostream& progress) {
  for (const auto& id : options.ids)
    if (registry.find(id) == nullptr) throw std::invalid_argument("unknown claim ID '" + id + "' (see claims --list)");
  ProveSummary summary;
  std::set<std::filesystem::path> decided;
  // Each round decides what the plan holds; a sentence built from an earlier answer joins the next round's.
  for (int round = 1; round <= 4; ++round) {
    progress << "==> collecting the proof plan" << (round > 1 ? " again" : "") << " (the checks at quick size)\n"
             << std::flush;
    const std::vector<proofs::PlannedRun> plan = collect_plan(registry, options);
    summary.planned = plan.size();
    std::vector<proofs::PlannedRun> todo;
    std::map<std::string, int> why;
    for (const proofs::PlannedRun& run : plan) {
      if (decided.contains(run.transcript_file())) continue;
      const std::string stale = proofs::staleness(run);
      // An attempt answers nothing: --all re-decides the proofs' runs only.
      if (stale.empty() && (!options.all || run.limits.attempt)) continue;
      ++why[stale.empty() ? "re-decided (--all)" : stale];
      todo.push_back(run);
    }
    progress << plan.size() << " decider runs in the plan; to decide: " << todo.size();
    for (const auto& [reason, n] : why) progress << (reason == why.begin()->first ? " (" : ", ") << reason << " " << n;
    progress << (why.empty() ? "\n" : ")\n") << std::flush;
    if (todo.empty()) break;
    for (proofs::ProvedRun& run : proofs::prove_plan(todo, options.jobs, progress)) {
      decided.insert(run.run.transcript_file());
      summary.decided.push_back(std::move(run));
    }
  }
  return summary;
}

}  // namespace affinterp::claims
