#include "experiments/claims/bench_results.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace affinterp::claims {

namespace {

/// The benchmark's own name: run names carry options set in code as extra components
/// ("exp3/affinterp/min_time:0.200/repeats:10"), which are dropped.
std::string base_name(const std::string& run_name) {
  std::string name;
  std::size_t begin = 0;
  while (begin <= run_name.size()) {
    const std::size_t end = std::min(run_name.find('/', begin), run_name.size());
    const std::string component = run_name.substr(begin, end - begin);
    if (component.find(':') == std::string::npos) name += (name.empty() ? "" : "/") + component;
    begin = end + 1;
  }
  return name;
}

}  // namespace

std::optional<double> BenchResults::operator[](std::string_view name) const {
  const auto it = median.find(name);
  if (it == median.end()) return std::nullopt;
  return it->second;
}

std::optional<BenchResults> read_bench_results(const std::filesystem::path& file, const std::string& counter) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  std::ifstream in(file);
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not JSON (" + e.what() + ")");
  }
  if (!json.contains("benchmarks") || !json["benchmarks"].is_array())
    throw std::runtime_error(file.string() + ": not a Google Benchmark output (no \"benchmarks\")");

  BenchResults results;
  results.file = file;
  const auto& context = json.value("context", nlohmann::json::object());
  results.machine = context.value("affinterp_cpu", "unknown (run a current bench executable)");
  results.compiler = context.value("affinterp_compiler", "unknown");
  results.flags = context.value("affinterp_flags", "unknown");
  for (const auto& run : json["benchmarks"]) {
    const std::string name = base_name(run.value("run_name", run.value("name", "")));
    if (run.value("error_occurred", false)) {
      results.errors[name] = run.value("error_message", "error");
      continue;
    }
    if (!run.contains(counter)) continue;
    // Repeated benchmarks report aggregates: take the median. A single run is its own median.
    const bool aggregate = run.value("run_type", "iteration") == "aggregate";
    if (!aggregate) results.repetitions[name].push_back(run[counter].get<double>());
    if (aggregate && run.value("aggregate_name", "") != "median") continue;
    if (!aggregate && results.median.contains(name)) continue;
    results.median[name] = run[counter].get<double>();
  }
  return results;
}

}  // namespace affinterp::claims
