#include "experiments/claims/engine_cli.hpp"

#include "experiments/bench/bench_results.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::claims {
namespace {

/// Issue 19: a frame through the CLI, writing included, within 1.3 times the engine's.
constexpr double target_ratio = 1.3;

}  // namespace

nlohmann::json engine_cli(const std::filesystem::path& bench_file) {
  const std::optional<bench::BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<bench::BenchResults> sizes = bench::read_bench_results(bench_file, "triangles");
  const std::optional<bench::BenchResults> extra = bench::read_bench_results(bench_file, "extra_frames");
  nlohmann::json table{{"file", bench_file.filename().string()},
                       {"machine", times->machine},
                       {"target_ratio", target_ratio},
                       {"rows", nlohmann::json::array()}};
  std::vector<Verdict> verdicts;
  for (const auto& [name, cli_ms] : times->median) {
    if (!name.starts_with("cli_frame/")) continue;  // cli_frame/<energy>/<triangles>
    const std::string rest = name.substr(10), engine = "engine_frame/" + rest;
    const std::optional<double> engine_ms = (*times)[engine];
    if (!engine_ms) continue;
    if (const auto triangles = sizes ? (*sizes)[name] : std::nullopt) table["triangles"] = *triangles;
    const Measured ratio = measured_ratio(*times, name, engine);
    const Interval band{0, target_ratio};
    verdicts.push_back(verdict_of(ratio, band));
    nlohmann::json row = to_json(ratio, band);  // ratio, its interval, repetitions, verdict
    row["energy"] = rest.substr(0, rest.find('/'));
    row["cli_frame_ms"] = cli_ms;
    row["engine_frame_ms"] = *engine_ms;
    if (const auto extra_frames = extra ? (*extra)[name] : std::nullopt) row["extra_frames"] = *extra_frames;
    const std::string memory = "cli_frame_memory/" + rest;  // the same CLI runs writing into memory
    if (const std::optional<double> memory_ms = (*times)[memory]) {
      const Measured memory_ratio = measured_ratio(*times, memory, engine);
      row["cli_memory_frame_ms"] = *memory_ms;
      row["memory_ratio"] = memory_ratio.value;
      row["memory_ratio_ci95"] = ci95_json(memory_ratio);
    }
    table["rows"].push_back(std::move(row));
  }
  table["verdict"] = verdicts.empty() ? nlohmann::json() : nlohmann::json(to_string(all_of(verdicts)));
  return table;
}

}  // namespace affinterp::claims
