#pragma once
// Runs a decider as a child process under limits, so that no sentence can hang the suite or take the
// machine's memory: a CPU-time limit (RLIMIT_CPU: whether a decider finishes does not depend on the machine's
// load), a wall-clock limit (the whole process group is killed) and an address-space cap (RLIMIT_AS). An
// interrupted run kills the group too (experiments/support/interrupt_cleanup.hpp).
#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::proofs {

struct ProcessLimits {
  double wall_seconds = 60;
  double cpu_seconds = 0;                                     ///< RLIMIT_CPU, rounded up; 0: none
  std::size_t address_space_bytes = std::size_t{1536} << 20;  ///< 1.5 GB
};

struct ProcessResult {
  std::string output;      ///< standard output and standard error, interleaved
  int exit_status = 0;     ///< the exit status, or 128 + signal number
  bool timed_out = false;  ///< killed at the wall-clock or the CPU-time limit
  bool not_found = false;  ///< the program could not be started
  double seconds = 0;      ///< wall time
  double cpu_seconds = 0;  ///< user + system CPU time of the child (wait4)
  long max_rss_kb = 0;     ///< the child's peak resident set size, in KiB (wait4)
};

/// Runs `argv` (argv[0] looked up in PATH) with standard input from `input` (or /dev/null when empty).
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& input,
                          const ProcessLimits& limits);

}  // namespace affinterp::proofs
