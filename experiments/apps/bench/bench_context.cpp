#include "experiments/apps/bench/bench_context.hpp"

#include "experiments/support/environment.hpp"

namespace affinterp::bench {

void add_machine_context() {
  const nlohmann::json environment = environment_description();
  for (const char* key : {"cpu", "compiler", "flags", "eigen", "os", "blas"})
    benchmark::AddCustomContext(std::string("affinterp_") + key, environment.at(key).get<std::string>());
  benchmark::AddCustomContext("affinterp_cpu_flags", cpu_flags());
}

int run_benchmarks(int argc, char** argv) {
  add_machine_context();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace affinterp::bench
