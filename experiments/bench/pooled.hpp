#pragma once
// One machine's runs pooled into one figure: the runs recorded with one machine key (machine_label.hpp) are
// resampled together by the hierarchical bootstrap (bootstrap.hpp: runs, then processes, then repetitions),
// the statistic being the run's own (speed_figures.hpp: a ratio of medians, or a monotone function of one
// median) over the pooled repetitions. More runs of one machine then narrow its interval where they agree and
// widen it where they drift, instead of each run being decided alone.
#include "experiments/bench/history.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::bench {

/// The runs of one machine, oldest first.
struct MachineRuns {
  std::string key;  ///< machine_key of its runs
  std::vector<const RecordedRun*> runs;
};

/// `runs` grouped by machine_key, machines in the order of their first run.
std::vector<MachineRuns> by_machine(const std::vector<RecordedRun>& runs);

/// The seed of every pooled interval (the per-run intervals' own, measured.hpp), and its resamples.
inline constexpr std::uint64_t kPooledSeed = kBootstrapSeed;
inline constexpr std::size_t kPooledResamples = kResamples;

/// The figure `key` of `machine`'s runs pooled: the statistic over every repetition of the runs that measured
/// it, and its 95% hierarchical bootstrap interval (kPooledSeed, kPooledResamples). A machine of one run keeps
/// that run's figure (the hierarchical bootstrap of one run is the run's own, draw for draw). Several runs give
/// no interval when one of them lacks one or its repetitions (an entry recorded without them). nullopt when no
/// run measured it.
std::optional<Measured> pooled_figure(const MachineRuns& machine, const std::string& key);

}  // namespace affinterp::bench
