#include "experiments/bench/merge_processes.hpp"

#include <fstream>
#include <stdexcept>

namespace affinterp::bench {

nlohmann::json merge_processes(const std::vector<std::filesystem::path>& processes) {
  if (processes.empty()) throw std::runtime_error("no benchmark output to merge");
  nlohmann::json merged{{"benchmarks", nlohmann::json::array()}};
  nlohmann::json dates = nlohmann::json::array();
  for (std::size_t k = 0; k < processes.size(); ++k) {
    std::ifstream in(processes[k]);
    if (!in) throw std::runtime_error(processes[k].string() + ": cannot read");
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (json.is_discarded() || !json.contains("benchmarks") || !json["benchmarks"].is_array())
      throw std::runtime_error(processes[k].string() + ": not a Google Benchmark output");
    const nlohmann::json context = json.value("context", nlohmann::json::object());
    if (k == 0) merged["context"] = context;
    dates.push_back(context.value("date", ""));
    for (nlohmann::json run : json["benchmarks"]) {
      if (run.value("run_type", "iteration") == "aggregate") continue;
      run["affinterp_process"] = k;
      merged["benchmarks"].push_back(std::move(run));
    }
  }
  merged["context"]["affinterp_processes"] = processes.size();
  merged["context"]["affinterp_process_dates"] = dates;
  return merged;
}

}  // namespace affinterp::bench
