// `affinterp bench`: merge the whole-process repetitions of a benchmark program into one file, and record a run of
// the benchmarks in the history the speed verdicts are decided over (experiments/bench/).
#include "experiments/apps/cli/command.hpp"
#include "experiments/bench/history.hpp"
#include "experiments/bench/merge_processes.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

struct MergeOptions {
  std::vector<std::string> processes;
  std::string out;
};

struct RecordOptions {
  std::string bench_dir = AFFINTERP_SOURCE_DIR "/reports/bench";
  std::string history;
  std::string note;
};

void merge(const MergeOptions& options) {
  nlohmann::json merged;
  try {
    merged = bench::merge_processes(std::vector<fs::path>(options.processes.begin(), options.processes.end()));
  } catch (const std::runtime_error& e) {
    throw CommandFailed(e.what(), 1);
  }
  const fs::path out(options.out), temporary(options.out + ".tmp");
  {
    std::ofstream file(temporary);
    file << merged.dump(2) << "\n";
    if (!file) throw CommandFailed("cannot write " + temporary.string(), 1);
  }
  fs::rename(temporary, out);
  std::cerr << "wrote " << out.string() << " (" << options.processes.size() << " processes)\n";
}

void record(const RecordOptions& options) {
  const fs::path history =
      options.history.empty() ? fs::path(options.bench_dir) / "history" : fs::path(options.history);
  try {
    const std::optional<bench::RecordedRun> run = bench::current_run(options.bench_dir, options.note);
    if (!run)
      throw CommandFailed(
          "no benchmark output (bench_exp3.json, bench_app3.json, bench_interp.json) in " + options.bench_dir, 1);
    const std::size_t before = bench::read_history(history).size();
    const fs::path file = bench::record(*run, history);
    std::cerr << (bench::read_history(history).size() > before ? "recorded " : "already recorded as ") << file.string()
              << "\n";
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CommandFailed*>(&e)) throw;
    throw CommandFailed(e.what(), 1);
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  CLI::App* cmd =
      app.add_subcommand("bench", "Merge benchmark processes and record runs in the history the speed verdicts read.");
  cmd->require_subcommand(1);

  auto merge_options = std::make_shared<MergeOptions>();
  CLI::App* merge_cmd = cmd->add_subcommand(
      "merge",
      "Merge the Google Benchmark JSON of whole processes of one program (run in interleaved order) into "
      "one file whose repetitions keep their process.");
  merge_cmd->add_option("processes", merge_options->processes, "The processes' JSON outputs, in run order")
      ->required()
      ->check(CLI::ExistingFile);
  merge_cmd->add_option("--out", merge_options->out, "The merged file")->required();
  merge_cmd->callback([merge_options] { merge(*merge_options); });

  auto record_options = std::make_shared<RecordOptions>();
  CLI::App* record_cmd = cmd->add_subcommand(
      "record",
      "Add the run in BENCH_DIR (its machine, date and speed figures with 95% intervals) to the history; "
      "a run already recorded is left as it is.");
  record_cmd->add_option("--bench-dir", record_options->bench_dir, "Folder of the benchmark outputs")
      ->capture_default_str();
  record_cmd->add_option("--history", record_options->history, "The history folder (default: BENCH_DIR/history)");
  record_cmd->add_option("--note", record_options->note,
                         "What to know about the run, e.g. that the machine was shared and loaded");
  record_cmd->callback([record_options] { record(*record_options); });
}

}  // namespace affinterp::cli
