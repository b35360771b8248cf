// The speed claims decided per machine (experiments/bench/pooled.hpp, experiments/claims/speed_verdict.hpp's
// across_machines, experiments/claims/sym3/speed_claim.hpp's decide_runs), on synthetic runs: a machine whose runs
// agree is decided on their pooled interval even when one run alone straddles the band's edge; machines on
// opposite sides make the claim machine-dependent, runs of one machine never do; the machine key; and the
// committed history's repetitions give back every run's recorded figures.
#include "experiments/bench/machine_label.hpp"
#include "experiments/bench/pooled.hpp"
#include "experiments/claims/sym3/speed_claim.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace affinterp::claims::pooled_machines_test {
namespace {

using V = Verdict;
const std::string kKey = "eig3/eigen-qr ÷ eig3/viete";
const sym3::Reading kReading{kKey, sym3::about_band(3.2), "Viète"};  // band [2.13, 4.80]

/// Ten repetitions spread evenly over value · (1 ± spread).
std::vector<double> repetitions(double value, double spread) {
  std::vector<double> x(10);
  for (int i = 0; i < 10; ++i) x[i] = value * (1 + spread * (2.0 * i / 9 - 1));
  return x;
}

/// A recorded run on `cpu` (flags avx2, g++ 12.2.0) timing eigen-qr at `ratio` times viete, two processes of ten
/// repetitions each spread ±spread; its own figure measured from them as a benchmark file's would be.
bench::RecordedRun run(const std::string& id, const std::string& cpu, double ratio, double spread) {
  bench::RecordedRun r;
  r.id = r.date = id;
  r.machine = {{"cpu", cpu}, {"cpu_flags", "sse2 avx avx2"}, {"compiler", "g++ 12.2.0"}, {"cores", 2}};
  r.repetitions["eig3/eigen-qr"] = {repetitions(100 * ratio, spread), repetitions(100 * ratio, spread)};
  r.repetitions["eig3/viete"] = {repetitions(100, 0.001), repetitions(100, 0.001)};
  bench::BenchResults results;
  for (const auto& [name, x] : r.repetitions) {
    results.repetitions[name] = x;
    results.median[name] = bench::median(bench::pooled(x));
  }
  r.figures[kKey] = {"bench_exp3", "×", bench::measured_ratio(results, "eig3/eigen-qr", "eig3/viete")};
  return r;
}

TEST(PooledMachines, TheMachineKeyIsModelVectorExtensionCompilerAndBuildFlags) {
  EXPECT_EQ(bench::machine_key({{"cpu", "AMD EPYC"},
                                {"cpu_flags", "avx avx2 avx512f"},
                                {"compiler", "g++ 12.2.0"},
                                {"flags", " -O3 -DNDEBUG -Wall -Wextra -march=native -ffp-contract=off"}}),
            "AMD EPYC, avx512f, g++ 12.2.0 -O3 -DNDEBUG -march=native -ffp-contract=off");
  EXPECT_EQ(bench::machine_key({{"cpu", "AMD EPYC"}}),
            "AMD EPYC, CPU flags not recorded, compiler not recorded, build flags not recorded");
  const std::vector<bench::RecordedRun> runs = {run("1", "A", 3, 0.01), run("2", "B", 3, 0.01), run("3", "A", 3, 0.01)};
  const std::vector<bench::MachineRuns> machines = bench::by_machine(runs);
  ASSERT_EQ(machines.size(), 2u);
  EXPECT_EQ(machines[0].runs.size(), 2u);
  EXPECT_EQ(machines[0].runs[1]->id, "3");
  bench::RecordedRun other_compiler = run("4", "A", 3, 0.01);
  other_compiler.machine["compiler"] = "clang++ 16.0.6";
  EXPECT_NE(bench::machine_key(other_compiler.machine), machines[0].key);
  nlohmann::json built = run("5", "A", 3, 0.01).machine, with_warnings = built, without_contraction = built;
  built["flags"] = "-O3 -march=native";
  with_warnings["flags"] = "-O3 -march=native -Wall -Wextra";
  without_contraction["flags"] = "-O3 -march=native -ffp-contract=off";
  EXPECT_EQ(bench::machine_key(with_warnings), bench::machine_key(built));
  EXPECT_NE(bench::machine_key(without_contraction), bench::machine_key(built));
}

TEST(PooledMachines, AStraddlingRunOfAnAgreeingMachineIsReproducedPooled) {
  // Five tight runs at 4.0 and one noisy run at 4.4 whose interval alone crosses 4.80: each run decided alone
  // leaves the claim inconclusive; pooled, the machine's interval lies in the band.
  std::vector<bench::RecordedRun> runs;
  for (int k = 0; k < 5; ++k) runs.push_back(run("tight-" + std::to_string(k), "A", 4.0, 0.01));
  runs.push_back(run("noisy", "A", 4.4, 0.25));
  const sym3::RunsDecision decision = sym3::decide_runs(runs, {kReading}, "test");
  EXPECT_EQ(decision.per_run.back(), V::inconclusive);
  EXPECT_EQ(across_machines(decision.per_run), V::inconclusive) << "each run a machine of its own (the old rule)";
  ASSERT_EQ(decision.per_machine.size(), 1u);
  EXPECT_EQ(decision.per_machine[0], V::reproduced) << decision.machine_table.dump();
  EXPECT_EQ(decision.verdict, V::reproduced);
  EXPECT_EQ(decision.machines[0]["runs"].size(), 6u);
  EXPECT_EQ(decision.runs.size(), 6u);
}

TEST(PooledMachines, MachinesOnOppositeSidesAreMachineDependent) {
  std::vector<bench::RecordedRun> runs = {run("a1", "A", 4.0, 0.01), run("a2", "A", 4.1, 0.01),
                                          run("b1", "B", 5.5, 0.01), run("b2", "B", 5.6, 0.01)};
  EXPECT_EQ(sym3::decide_runs(runs, {kReading}, "test").verdict, V::machine_dependent);
  // The same four runs on one machine: the runs disagree, but one machine cannot depend on itself.
  for (bench::RecordedRun& r : runs) r.machine["cpu"] = "A";
  const sym3::RunsDecision one = sym3::decide_runs(runs, {kReading}, "test");
  EXPECT_EQ(across_machines(one.per_run), V::machine_dependent) << "each run a machine of its own (the old rule)";
  EXPECT_NE(one.verdict, V::machine_dependent);
}

TEST(PooledMachines, AcrossMachinesAgreesOrDependsOrIsUndecided) {
  const auto across = [](std::vector<V> machines) { return across_machines(machines); };
  EXPECT_EQ(across({V::reproduced, V::reproduced}), V::reproduced);
  EXPECT_EQ(across({V::not_reproduced}), V::not_reproduced);
  EXPECT_EQ(across({V::reproduced, V::inconclusive, V::not_reproduced}), V::machine_dependent);
  EXPECT_EQ(across({V::reproduced, V::inconclusive}), V::inconclusive);
  EXPECT_EQ(across({}), V::inconclusive);
}

TEST(PooledMachines, AMachineOfOneRunKeepsItsInterval) {
  const bench::RecordedRun only = run("1", "A", 3.3, 0.05);
  const std::vector<bench::RecordedRun> runs = {only};
  const auto pooled = bench::pooled_figure(bench::by_machine(runs).front(), kKey);
  ASSERT_TRUE(pooled && pooled->ci95 && only.figures.at(kKey).measured.ci95);
  EXPECT_EQ(pooled->ci95->lo, only.figures.at(kKey).measured.ci95->lo);
  EXPECT_EQ(pooled->ci95->hi, only.figures.at(kKey).measured.ci95->hi);
}

TEST(PooledMachines, RunsWithoutRepetitionsGiveNoPooledInterval) {
  std::vector<bench::RecordedRun> runs = {run("1", "A", 3.3, 0.01), run("2", "A", 3.4, 0.01)};
  runs[1].repetitions.clear();  // an entry recorded before runs kept their repetitions
  const auto pooled = bench::pooled_figure(bench::by_machine(runs).front(), kKey);
  ASSERT_TRUE(pooled.has_value());
  EXPECT_FALSE(pooled->ci95.has_value());
  EXPECT_EQ(sym3::decide_runs(runs, {kReading}, "test").verdict, V::inconclusive);
}

TEST(PooledMachines, TheCommittedHistorysRepetitionsGiveBackEachRunsFigures) {
  // Every committed entry's speed-claim figures, recomputed from the repetitions it stores, are the value and
  // interval it recorded: the pooled intervals read the data the runs were decided on.
  const std::vector<bench::RecordedRun> runs =
      bench::read_history(std::filesystem::path(AFFINTERP_SOURCE_DIR) / "reports/bench/history");
  ASSERT_GE(runs.size(), 14u);
  for (const bench::RecordedRun& r : runs)
    for (const auto& [key, figure] : r.figures) {
      if (figure.unit != "×" || !figure.measured.ci95) continue;
      const bench::FigureReads reads = bench::figure_reads(key);
      bench::BenchResults results;
      for (const std::string& name : reads.benchmarks) {
        ASSERT_TRUE(r.repetitions.contains(name)) << r.id << ": " << name;
        results.repetitions[name] = r.repetitions.at(name);
        results.median[name] = bench::median(bench::pooled(results.repetitions[name]));
      }
      const Measured m = bench::measured_ratio(results, reads.benchmarks[0], reads.benchmarks[1]);
      EXPECT_DOUBLE_EQ(m.value, figure.measured.value) << r.id << ": " << key;
      ASSERT_TRUE(m.ci95.has_value()) << r.id << ": " << key;
      EXPECT_DOUBLE_EQ(m.ci95->lo, figure.measured.ci95->lo) << r.id << ": " << key;
      EXPECT_DOUBLE_EQ(m.ci95->hi, figure.measured.ci95->hi) << r.id << ": " << key;
    }
}

}  // namespace
}  // namespace affinterp::claims::pooled_machines_test
