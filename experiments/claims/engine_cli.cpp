#include "experiments/claims/engine_cli.hpp"

#include "experiments/bench/bench_results.hpp"

#include <optional>
#include <string>

namespace affinterp::claims {
namespace {

/// Issue 19: a frame through the CLI, writing included, within 1.3 times the engine's.
constexpr double target_ratio = 1.3;

}  // namespace

nlohmann::json engine_cli(const std::filesystem::path& bench_file) {
  const std::optional<bench::BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<bench::BenchResults> sizes = bench::read_bench_results(bench_file, "triangles");
  nlohmann::json table{{"file", bench_file.filename().string()},
                       {"machine", times->machine},
                       {"target_ratio", target_ratio},
                       {"rows", nlohmann::json::array()},
                       {"met", true}};
  for (const auto& [name, cli_ms] : times->median) {
    if (!name.starts_with("cli_frame/")) continue;  // cli_frame/<energy>/<triangles>
    const std::string rest = name.substr(10);
    const std::optional<double> engine_ms = (*times)["engine_frame/" + rest];
    if (!engine_ms) continue;
    if (const auto triangles = sizes ? (*sizes)[name] : std::nullopt) table["triangles"] = *triangles;
    const double ratio = cli_ms / *engine_ms;
    const bool met = ratio <= target_ratio;
    table["rows"].push_back({{"energy", rest.substr(0, rest.find('/'))},
                             {"cli_frame_ms", cli_ms},
                             {"engine_frame_ms", *engine_ms},
                             {"ratio", ratio},
                             {"met", met}});
    table["met"] = table["met"].get<bool>() && met;
  }
  if (table["rows"].empty()) table["met"] = nullptr;
  return table;
}

}  // namespace affinterp::claims
