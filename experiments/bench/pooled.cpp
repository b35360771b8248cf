#include "experiments/bench/pooled.hpp"

#include "experiments/bench/machine_label.hpp"

#include <algorithm>

namespace affinterp::bench {

namespace {

/// The samples of `figure_reads(key).benchmarks` in each run, or nullopt when a run lacks one or its interval.
std::optional<std::vector<RunSamples>> samples_of(const std::vector<const RecordedRun*>& runs, const FigureReads& reads,
                                                  const std::string& key) {
  std::vector<RunSamples> samples;
  for (const RecordedRun* run : runs) {
    if (!run->figures.at(key).measured.ci95) return std::nullopt;
    RunSamples& run_samples = samples.emplace_back();
    for (const std::string& benchmark : reads.benchmarks) {
      const auto found = run->repetitions.find(benchmark);
      if (found == run->repetitions.end()) return std::nullopt;
      run_samples.push_back(found->second);
    }
  }
  return samples;
}

/// The figure over the pooled repetitions and its hierarchical interval (measured.hpp's rule, runs drawn too).
Measured pooled_measured(const std::vector<RunSamples>& samples, const FigureReads& reads) {
  std::vector<std::vector<double>> all(reads.benchmarks.size());
  std::size_t processes = 0;
  for (const RunSamples& run : samples) {
    processes += run.front().size();
    for (std::size_t s = 0; s < run.size(); ++s) {
      const std::vector<double> repetitions = pooled(run[s]);
      all[s].insert(all[s].end(), repetitions.begin(), repetitions.end());
    }
  }
  const std::size_t repetitions =
      std::ranges::min(all, {}, [](const std::vector<double>& x) { return x.size(); }).size();
  if (!reads.of_median) {
    const Statistic ratio = [](const auto& s) { return median(s[0]) / median(s[1]); };
    return {ratio(all), hierarchical_interval(samples, ratio, kPooledSeed, 0.95, kPooledResamples), repetitions,
            processes};
  }
  const Interval ci = hierarchical_interval(
      samples, [](const auto& s) { return median(s[0]); }, kPooledSeed, 0.95, kPooledResamples);
  const double a = reads.of_median(ci.lo), b = reads.of_median(ci.hi);
  return {reads.of_median(median(all[0])), Interval{std::min(a, b), std::max(a, b)}, repetitions, processes};
}

}  // namespace

std::vector<MachineRuns> by_machine(const std::vector<RecordedRun>& runs) {
  std::vector<MachineRuns> machines;
  for (const RecordedRun& run : runs) {
    const std::string key = machine_key(run.machine);
    auto machine = std::ranges::find(machines, key, &MachineRuns::key);
    if (machine == machines.end()) machine = machines.insert(machines.end(), MachineRuns{key, {}});
    machine->runs.push_back(&run);
  }
  return machines;
}

std::optional<Measured> pooled_figure(const MachineRuns& machine, const std::string& key) {
  std::vector<const RecordedRun*> measured;
  for (const RecordedRun* run : machine.runs)
    if (run->figures.contains(key)) measured.push_back(run);
  if (measured.empty()) return std::nullopt;
  if (measured.size() == 1) return measured.front()->figures.at(key).measured;
  const FigureReads reads = figure_reads(key);
  const std::optional<std::vector<RunSamples>> samples = samples_of(measured, reads, key);
  if (samples) return pooled_measured(*samples, reads);
  Measured without{0, std::nullopt, 0, 0};  // the median of the runs' figures, undecided
  std::vector<double> values;
  for (const RecordedRun* run : measured) {
    const Measured& m = run->figures.at(key).measured;
    values.push_back(m.value);
    without.repetitions += m.repetitions;
    without.processes += m.processes;
  }
  without.value = median(values);
  return without;
}

}  // namespace affinterp::bench
