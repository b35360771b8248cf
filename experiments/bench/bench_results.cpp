#include "experiments/bench/bench_results.hpp"

#include "experiments/bench/machine_label.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace affinterp::bench {

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
  const auto& context = results.context = json.value("context", nlohmann::json::object());
  results.machine = machine_label(context.value("affinterp_cpu", nlohmann::json()),
                                  context.value("affinterp_cpu_flags", nlohmann::json()));
  results.compiler = context.value("affinterp_compiler", "unknown");
  results.flags = context.value("affinterp_flags", "unknown");
  std::map<std::string, std::map<std::int64_t, std::vector<double>>> by_process;
  for (const auto& run : json["benchmarks"]) {
    const std::string name = base_name(run.value("run_name", run.value("name", "")));
    if (run.value("error_occurred", false)) {
      results.errors[name] = run.value("error_message", "error");
      continue;
    }
    if (!run.contains(counter)) continue;
    const double value = run[counter].get<double>();
    // Repeated benchmarks report aggregates: take the median; a single run is its own median. The repetitions
    // themselves, where the file keeps them, decide the median below.
    if (run.value("run_type", "iteration") == "aggregate") {
      if (run.value("aggregate_name", "") == "median" && !results.median.contains(name)) results.median[name] = value;
      continue;
    }
    by_process[name][run.value("affinterp_process", std::int64_t{0})].push_back(value);
  }
  for (auto& [name, processes] : by_process) {
    ByProcess& x = results.repetitions[name];
    for (auto& [index, values] : processes) x.push_back(std::move(values));
    results.median[name] = bench::median(pooled(x));
  }
  return results;
}

}  // namespace affinterp::bench
