// The speed verdicts of thesis §3.4 (experiments/claims/sym3/thesis_*_speedup.cpp) on synthetic benchmark
// JSON: absent data is inconclusive, and the verdict follows the ratio's bootstrap interval against the
// band the wording allows: inside, outside, straddling an edge, or without enough repetitions.
#include "experiments/claims/registry.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace affinterp::claims::speed_claims_test {
namespace {

namespace fs = std::filesystem;

/// Writes bench_<name>.json in Google Benchmark's format, as bench_exp3 writes it: `repetitions` runs per
/// benchmark spread evenly over value · (1 ± spread) (median: value), then the mean and median aggregates;
/// run names carry the options set in code. Returns its folder.
fs::path write_bench(const std::string& bench, const std::string& counter, const std::map<std::string, double>& times,
                     double spread = 0.01, int repetitions = 10) {
  // One folder per test and call: CTest runs the tests in parallel processes.
  static int call = 0;
  const fs::path dir =
      fs::temp_directory_path() /
      ("affinterp_speed_test_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
       std::to_string(++call));
  fs::create_directories(dir);
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& [name, value] : times) {
    const std::string run_name = name + "/min_time:0.200/repeats:" + std::to_string(repetitions);
    for (int i = 0; i < repetitions; ++i) {
      const double offset = repetitions > 1 ? 2.0 * i / (repetitions - 1) - 1 : 0;
      runs.push_back({{"name", run_name},
                      {"run_name", run_name},
                      {"run_type", "iteration"},
                      {"repetition_index", i},
                      {counter, value * (1 + spread * offset)}});
    }
    runs.push_back({{"name", run_name + "_mean"},
                    {"run_name", run_name},
                    {"run_type", "aggregate"},
                    {"aggregate_name", "mean"},
                    {counter, 2 * value}});
    runs.push_back({{"name", run_name + "_median"},
                    {"run_name", run_name},
                    {"run_type", "aggregate"},
                    {"aggregate_name", "median"},
                    {counter, value}});
  }
  std::ofstream(dir / (bench + ".json")) << nlohmann::json{
      {"context", {{"affinterp_cpu", "Test CPU"}}},
      {"benchmarks", runs}}.dump();
  return dir;
}

/// The outcome of a declared claim's check run on the benchmark files of `bench_dir`.
Outcome run_on(std::string_view claim_id, const fs::path& bench_dir) {
  RunContext run;
  run.bench_dir = bench_dir;
  return registered_claims().find(claim_id)->check(run.for_claim(claim_id));
}
Outcome check_eig_speedup(const fs::path& bench_dir) { return run_on("thesis.eig.speedup", bench_dir); }
Outcome check_exp_speedup(const fs::path& bench_dir) { return run_on("thesis.exp.speedup", bench_dir); }
Outcome check_app_speedup(const fs::path& bench_dir) { return run_on("thesis.app.speedup", bench_dir); }

TEST(SpeedClaims, AreInconclusiveWithoutBenchmarkData) {
  const fs::path nowhere = fs::temp_directory_path() / "affinterp_no_such_folder";
  for (auto check : {check_eig_speedup, check_exp_speedup, check_app_speedup}) {
    const Outcome outcome = check(nowhere);
    EXPECT_EQ(outcome.verdict, Verdict::inconclusive);
    EXPECT_NE(outcome.summary.find("bench_"), std::string::npos) << outcome.summary;
  }
}

TEST(SpeedClaims, EigenvalueVerdictFollowsTheMeasuredRatio) {
  auto near = write_bench("bench_exp3", "ns_per_matrix", {{"eig3/eigen-qr", 100}, {"eig3/viete", 30}});
  const Outcome reproduced = check_eig_speedup(near);
  EXPECT_EQ(reproduced.verdict, Verdict::reproduced) << reproduced.summary;
  const nlohmann::json& m = reproduced.evidence.measurements;
  EXPECT_NEAR(m["ratio"].get<double>(), 100.0 / 30, 1e-12);
  EXPECT_LT(m["ratio_ci95"][0].get<double>(), 100.0 / 30);
  EXPECT_GT(m["ratio_ci95"][1].get<double>(), 100.0 / 30);
  EXPECT_NEAR(m["band"][0].get<double>(), 3.2 / 1.5, 1e-12);
  EXPECT_NEAR(m["band"][1].get<double>(), 3.2 * 1.5, 1e-12);
  EXPECT_EQ(m["repetitions"], 10);
  EXPECT_EQ(m["machine"]["cpu"], "Test CPU");

  auto far = write_bench("bench_exp3", "ns_per_matrix", {{"eig3/eigen-qr", 100}, {"eig3/viete", 90}});
  EXPECT_EQ(check_eig_speedup(far).verdict, Verdict::not_reproduced);
}

TEST(SpeedClaims, AnIntervalAcrossABandEdgeIsInconclusive) {
  // Ratio 4.8 = 3.2 · 1.5, the band's upper edge, measured with ±10% spread.
  auto edge = write_bench("bench_exp3", "ns_per_matrix", {{"eig3/eigen-qr", 480}, {"eig3/viete", 100}}, 0.1);
  const Outcome outcome = check_eig_speedup(edge);
  EXPECT_EQ(outcome.verdict, Verdict::inconclusive) << outcome.summary;
  EXPECT_LT(outcome.evidence.measurements["ratio_ci95"][0].get<double>(), 4.8);
  EXPECT_GT(outcome.evidence.measurements["ratio_ci95"][1].get<double>(), 4.8);
  // The same ratio measured tightly just inside the band is reproduced.
  auto inside = write_bench("bench_exp3", "ns_per_matrix", {{"eig3/eigen-qr", 470}, {"eig3/viete", 100}}, 0.001);
  EXPECT_EQ(check_eig_speedup(inside).verdict, Verdict::reproduced);
}

TEST(SpeedClaims, FewerThanTenRepetitionsAreInconclusive) {
  auto few = write_bench("bench_exp3", "ns_per_matrix", {{"eig3/eigen-qr", 100}, {"eig3/viete", 30}}, 0.01, 5);
  const Outcome outcome = check_eig_speedup(few);
  EXPECT_EQ(outcome.verdict, Verdict::inconclusive) << outcome.summary;
  EXPECT_TRUE(outcome.evidence.measurements["ratio_ci95"].is_null());
  EXPECT_NE(outcome.summary.find("no interval"), std::string::npos) << outcome.summary;
}

TEST(SpeedClaims, ExponentialNeedsPlainSdInBetween) {
  auto ordered =
      write_bench("bench_exp3", "ns_per_matrix",
                  {{"exp3/eigen-qr-diag", 420}, {"exp3/thesis-sd-corrected", 200}, {"exp3/thesis-improved-sd", 100}});
  EXPECT_EQ(check_exp_speedup(ordered).verdict, Verdict::reproduced);
  auto disordered =
      write_bench("bench_exp3", "ns_per_matrix",
                  {{"exp3/eigen-qr-diag", 420}, {"exp3/thesis-sd-corrected", 90}, {"exp3/thesis-improved-sd", 100}});
  EXPECT_EQ(check_exp_speedup(disordered).verdict, Verdict::not_reproduced);
}

TEST(SpeedClaims, TheBatchedExponentialsTimeIsSplitIntoItsExponentialsAndTheRest) {
  auto run = write_bench("bench_exp3", "ns_per_matrix",
                         {{"exp3/eigen-qr-diag", 420},
                          {"exp3/thesis-sd-corrected", 200},
                          {"exp3/thesis-improved-sd", 100},
                          {"exp3/affinterp-batched", 16},
                          {"exp3-parts/affinterp-batched-exponentials", 9}});
  const auto parts = check_exp_speedup(run).evidence.measurements["affinterp_targets"]["batched_ns_per_matrix_parts"];
  ASSERT_TRUE(parts.is_object());
  EXPECT_DOUBLE_EQ(parts["four_exponentials"].get<double>(), 9);
  EXPECT_DOUBLE_EQ(parts["split_assembly_and_layout"].get<double>(), 7);
}

TEST(SpeedClaims, ApplicationSlowdownIsNotReproduced) {
  auto slower =
      write_bench("bench_app3", "ns_per_frame", {{"app/eigen-qr-diag", 10e6}, {"app/thesis-improved-sd", 11e6}});
  EXPECT_EQ(check_app_speedup(slower).verdict, Verdict::not_reproduced);
  auto faster =
      write_bench("bench_app3", "ns_per_frame", {{"app/eigen-qr-diag", 12e6}, {"app/thesis-improved-sd", 10e6}});
  EXPECT_EQ(check_app_speedup(faster).verdict, Verdict::reproduced);
}

TEST(SpeedClaims, UnreadableBenchmarkOutputIsInconclusive) {
  const fs::path dir = fs::temp_directory_path() / "affinterp_speed_test_unreadable";
  fs::create_directories(dir);
  std::ofstream(dir / "bench_exp3.json") << "{\"benchmarks\": [{\"cv\": NaN}]}";
  const Outcome outcome = check_eig_speedup(dir);
  EXPECT_EQ(outcome.verdict, Verdict::inconclusive);
  EXPECT_NE(outcome.summary.find("unreadable"), std::string::npos) << outcome.summary;
}

TEST(SpeedClaims, ApplicationWithoutMeshDataIsInconclusive) {
  const fs::path dir = fs::temp_directory_path() / "affinterp_speed_test_no_mesh";
  fs::create_directories(dir);
  nlohmann::json runs = nlohmann::json::array();
  for (const char* name : {"app/eigen-qr-diag", "app/thesis-improved-sd"})
    runs.push_back({{"name", name},
                    {"run_name", name},
                    {"run_type", "iteration"},
                    {"error_occurred", true},
                    {"error_message", "the CGAL demo data is absent"}});
  std::ofstream(dir / "bench_app3.json") << nlohmann::json{
      {"context", nlohmann::json::object()},
      {"benchmarks", runs}}.dump();
  const Outcome outcome = check_app_speedup(dir);
  EXPECT_EQ(outcome.verdict, Verdict::inconclusive);
  EXPECT_NE(outcome.summary.find("CGAL demo data is absent"), std::string::npos) << outcome.summary;
}

}  // namespace
}  // namespace affinterp::claims::speed_claims_test
