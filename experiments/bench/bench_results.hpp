#pragma once
// Reading the Google Benchmark JSON written by build/bin/bench_* (experiments/reproduce.sh stores it in
// reports/bench/, whole processes merged by merge_processes.hpp), for the speed claims of thesis §3.4 and the
// global engine's speed table.
#include "experiments/bench/bootstrap.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::bench {

struct BenchResults {
  std::filesystem::path file;
  std::string machine;  ///< the CPU model and its widest vector extension, from the JSON context (machine_label.hpp)
  std::string compiler, flags;
  nlohmann::json context;  ///< the file's whole "context" (machine, date, processes)
  /// Per benchmark name (without aggregate suffix): the median of `counter` over every repetition of every
  /// process, or the file's median aggregate where it holds only aggregates.
  std::map<std::string, double, std::less<>> median;
  /// Per benchmark name: `counter` of each repetition, grouped by process (the "affinterp_process" index that
  /// merge_processes.hpp adds; one process without it), in run order; empty where the file holds only
  /// aggregates.
  std::map<std::string, ByProcess, std::less<>> repetitions;
  /// Benchmarks that reported an error (e.g. missing data), with the message.
  std::map<std::string, std::string, std::less<>> errors;

  /// The median of a benchmark; nullopt when it did not run.
  std::optional<double> operator[](std::string_view name) const;
};

/// Reads `file` and takes `counter` (e.g. "ns_per_matrix") of each benchmark; nullopt when the file is
/// absent. Throws std::runtime_error when it is not a Google Benchmark JSON file.
std::optional<BenchResults> read_bench_results(const std::filesystem::path& file, const std::string& counter);

}  // namespace affinterp::bench
