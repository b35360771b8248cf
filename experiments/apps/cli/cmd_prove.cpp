// `affinterp prove`: decide the proofs' sentences whose stored answers are missing or stale (proofs as data);
// `--all --check` re-decides every one and fails when an answer differs from the committed one.
#include "experiments/apps/cli/command.hpp"
#include "experiments/claims/prover.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;
using namespace affinterp::claims;

struct ProveCommand {
  ProveOptions options;
  std::string answers = RunSettings::committed_answers().string();
  bool check = false;
};

/// A copy of the store that --check decides into, removed afterwards: the committed answers stay as they are.
class ScratchStore {
 public:
  explicit ScratchStore(const fs::path& store) {
    std::string pattern = (fs::temp_directory_path() / "affinterp-prove-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw CommandFailed("cannot create a temporary folder", 1);
    path_ = fs::path(pattern) / "proofs";
    if (fs::exists(store)) fs::copy(store, path_, fs::copy_options::recursive);
  }
  ~ScratchStore() {
    std::error_code ignored;
    fs::remove_all(path_.parent_path(), ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void run(ProveCommand command) {
  std::optional<ScratchStore> scratch;
  if (command.check) scratch.emplace(command.answers);
  command.options.answer_dir = scratch ? scratch->path() : fs::path(command.answers);
  ProveSummary summary;
  try {
    summary = prove_claims(registered_claims(), command.options, std::cerr);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
  std::size_t changed = 0;
  for (const proofs::ProvedRun& r : summary.decided)
    if (r.before != r.after) {
      ++changed;
      std::cout << (r.before == "missing" ? "new:     " : "changed: ") << r.run.store.filename().string() << "/"
                << r.run.sentence << " " << r.run.decider.tool << ": " << r.after
                << (r.before == "missing" ? "" : " (stored: " + r.before + ")") << "\n";
    }
  std::cout << summary.planned << " decider runs in the plan, " << summary.decided.size() << " decided now, " << changed
            << " with an answer other than the stored one"
            << (command.check ? " (--check: " + command.answers + " left as it was)" : "") << "\n";
  if (command.check && changed > 0)
    throw CommandFailed(std::to_string(changed) + " answer(s) differ from the committed ones in " + command.answers, 1);
}

}  // namespace

void add_prove_command(CLI::App& app) {
  auto command = std::make_shared<ProveCommand>();
  CLI::App* cmd = app.add_subcommand(
      "prove",
      "Decide the proofs' sentences (QEPCAD B, Z3, cvc5) whose stored answers are missing or stale, and store the "
      "transcripts the claims read. A stored answer is stale when the sentence's text or the decider's version "
      "changed.");
  cmd->add_option("ids", command->options.ids, "Only the proofs of these claim IDs (default: every claim)");
  cmd->add_flag("--all", command->options.all, "Re-decide every sentence, not only the missing or stale ones");
  cmd->add_flag("--check", command->check,
                "Decide into a scratch copy of the store and fail when any answer differs from the stored one "
                "(with --all: reproduce every committed answer)");
  cmd->add_option("--answers", command->answers, "The store of transcripts, one folder per claim")
      ->capture_default_str();
  command->options.jobs = std::max(1u, std::thread::hardware_concurrency());
  cmd->add_option("--jobs", command->options.jobs, "Deciders at once, one core each")
      ->check(CLI::Range(1u, 64u))
      ->capture_default_str();
  cmd->callback([command] { run(*command); });
}

}  // namespace affinterp::cli
