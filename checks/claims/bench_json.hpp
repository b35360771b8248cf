#pragma once
// Google Benchmark JSON as the benchmark programs write it, for the tests of the tables read from it.
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

namespace affinterp::claims {

/// Ten repetitions spread evenly over ms · (1 ± spread), then their median aggregate, as bench_interp writes
/// them.
inline nlohmann::json repeated(const std::string& name, double ms, double triangles = 0, double spread = 0.01) {
  nlohmann::json runs = nlohmann::json::array();
  const std::string run_name = name + "/min_time:1.000/repeats:10";
  for (int i = 0; i < 10; ++i)
    runs.push_back({{"name", run_name},
                    {"run_name", run_name},
                    {"run_type", "iteration"},
                    {"repetition_index", i},
                    {"real_time", ms * (1 + spread * (2.0 * i / 9 - 1))},
                    {"time_unit", "ms"}});
  runs.push_back({{"name", run_name + "_median"},
                  {"run_name", run_name},
                  {"run_type", "aggregate"},
                  {"aggregate_name", "median"},
                  {"real_time", ms},
                  {"time_unit", "ms"}});
  if (triangles > 0)
    for (auto& run : runs) run["triangles"] = triangles;
  return runs;
}

/// `runs` (as repeated() writes them) with the user counter `counter` = `value` on each.
inline nlohmann::json with_counter(nlohmann::json runs, const std::string& counter, double value) {
  for (auto& run : runs) run[counter] = value;
  return runs;
}

inline nlohmann::json concatenated(std::initializer_list<nlohmann::json> parts) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace affinterp::claims
