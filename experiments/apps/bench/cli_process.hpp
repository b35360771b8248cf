#pragma once
// `affinterp` run as a user runs it, for the benchmarks that time the CLI end to end (bench_figures,
// bench_cli_scale): a child process with its output thrown away, timed from outside.
#include <string>
#include <vector>

namespace affinterp::bench {

struct ProcessRun {
  double seconds;  ///< wall-clock, from the spawn to the child's exit
  double peak_mb;  ///< the child's peak resident memory
};

/// Runs `cli` with `args` (stdout and stderr to /dev/null); throws std::runtime_error when it cannot start or
/// does not exit with 0.
ProcessRun run_cli(const std::string& cli, const std::vector<std::string>& args);

}  // namespace affinterp::bench
