#include "experiments/proofs/proof_plan.hpp"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <stdexcept>
#include <thread>

namespace affinterp::proofs {

namespace {

std::string stored_answer(const PlannedRun& run) {
  const std::optional<Transcript> t = read_transcript(run.transcript_file());
  return t && t->answers(run.decider.tool, run.input_text)
             ? std::string(to_string(answer_of(*t, run.input_text).result))
             : "missing";
}

void write_input(const PlannedRun& run) {
  std::filesystem::create_directories(run.store);
  const std::filesystem::path temporary = run.input_file().string() + ".partial";
  {
    std::ofstream out(temporary);
    out << run.input_text;
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, run.input_file());
}

}  // namespace

void ProofPlan::add(PlannedRun run) {
  const std::lock_guard lock(mutex_);
  runs_.push_back(std::move(run));
}

std::vector<PlannedRun> ProofPlan::runs() const {
  const std::lock_guard lock(mutex_);
  return runs_;
}

std::string staleness(const PlannedRun& run) {
  const std::optional<Transcript> t = read_transcript(run.transcript_file());
  if (!t) return "missing";
  if (!t->answers(run.decider.tool, run.input_text)) return "input changed";
  if (const std::string now = installed_version(run.decider); t->version != now)
    return "decider version " + t->version + " → " + now;
  return "";
}

std::vector<ProvedRun> prove_plan(const std::vector<PlannedRun>& runs, unsigned jobs, std::ostream& progress) {
  for (const PlannedRun& run : runs)
    if (installed_version(run.decider).empty())
      throw std::runtime_error(std::string(run.decider.tool) + " is not installed (Debian package " +
                               std::string(run.decider.debian_package) + ")");
  std::vector<ProvedRun> proved(runs.size());
  std::atomic<std::size_t> next{0};
  std::mutex progress_mutex;
  const auto worker = [&] {
    for (std::size_t k; (k = next++) < runs.size();) {
      const PlannedRun& run = runs[k];
      proved[k] = {run, stored_answer(run), ""};
      write_input(run);
      // The CPU-time limit decides; the wall-clock backstop is wide, so that a loaded machine changes no answer.
      DeciderLimits limits = run.limits;
      limits.wall_factor = std::max(limits.wall_factor, 10.0);
      const Transcript t = run_decider(run.decider, run.input_file(), run.input_text, limits);
      write_transcript(run.transcript_file(), t);
      proved[k].after = std::string(to_string(answer_of(t, run.input_text).result));
      const std::lock_guard lock(progress_mutex);
      progress << "[" << k + 1 << "/" << runs.size() << "] " << run.transcript_file().parent_path().filename().string()
               << "/" << run.sentence << " " << run.decider.tool << ": " << proved[k].after << " (" << std::fixed
               << std::setprecision(1) << t.seconds << " s)"
               << (proved[k].before != proved[k].after && proved[k].before != "missing" ? ", was " + proved[k].before
                                                                                        : "")
               << "\n"
               << std::flush;
    }
  };
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < std::max(1u, jobs); ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  return proved;
}

}  // namespace affinterp::proofs
