#pragma once
// The history of benchmark runs: one committed entry per run of the benchmarks, under
// reports/bench/history/, each naming its machine (CPU model and flags, cores, compiler and flags, library
// versions), its date, how many whole processes each program ran in, every speed figure with its 95%
// bootstrap interval (speed_figures.hpp), and the repetitions those figures were computed from. Entries are kept
// side by side, one per run; the speed verdicts pool the runs of one machine (pooled.hpp) and decide across
// machines (experiments/claims/speed_verdict.hpp).
#include "experiments/bench/speed_figures.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace affinterp::bench {

/// One run of the benchmark programs on one machine.
struct RecordedRun {
  std::string id;          ///< the entry's file stem: its date, then its machine ("<date>-intel-xeon-processor")
  std::string date;        ///< when its first benchmark process started (ISO 8601)
  nlohmann::json machine;  ///< as its benchmark files recorded it: cpu, cpu_flags, cores, compiler, flags, ...
  std::string note;        ///< what the recorder said about the run (e.g. a shared, loaded machine)
  /// Per program: {"processes": whole processes, "dates": each process's start}; identifies the run.
  nlohmann::json programs = nlohmann::json::object();
  std::map<std::string, Figure> figures;
  /// Per benchmark a figure reads (figure_reads): its repetitions by process, which pool the runs of one machine
  /// (pooled.hpp); empty in an entry recorded without them.
  std::map<std::string, ByProcess> repetitions;
  bool recorded = true;  ///< false for the benchmark files of a folder that no entry records yet
};

/// The history entry of the benchmark outputs in `bench_dir` (bench_exp3.json, bench_app3.json,
/// bench_interp.json, whichever exist), with `note`; nullopt when none exists. Throws std::runtime_error on an
/// unreadable benchmark file.
std::optional<RecordedRun> current_run(const std::filesystem::path& bench_dir, const std::string& note = "");

/// An entry as JSON, and back (throws std::runtime_error naming what is missing).
nlohmann::json to_json(const RecordedRun& run);
RecordedRun run_from_json(const nlohmann::json& json, const std::string& id);

/// Every entry of `history_dir` (*.json), oldest first; none when the folder is absent. Throws
/// std::runtime_error naming the file on a malformed entry.
std::vector<RecordedRun> read_history(const std::filesystem::path& history_dir);

/// The runs speed verdicts are decided over: the entries of bench_dir/history, and the benchmark files of
/// `bench_dir` themselves when no entry records them (recorded = false), last.
std::vector<RecordedRun> runs_of(const std::filesystem::path& bench_dir);

/// Adds `run` to `history_dir` as <date>-<cpu>.json (-2, -3, ... when taken); returns the file, or the existing
/// entry's file when an entry records the same benchmark processes already.
std::filesystem::path record(const RecordedRun& run, const std::filesystem::path& history_dir);

}  // namespace affinterp::bench
