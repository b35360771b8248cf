#include "experiments/bench/machine_label.hpp"

#include <sstream>

namespace affinterp::bench {

std::string widest_vector_isa(const std::string& flags) {
  const std::string list = " " + flags + " ";  // each flag between spaces
  for (const char* isa : {"avx512f", "avx2", "avx", "sse4_2"}) {
    std::string flag = " ";  // appended: GCC 12 misreports " " + isa + " " (-Wrestrict)
    flag += isa;
    flag += ' ';
    if (list.find(flag) != std::string::npos) return isa;
  }
  return "no AVX";
}

std::string machine_label(const nlohmann::json& cpu, const nlohmann::json& flags) {
  const std::string name = cpu.is_string() ? cpu.get<std::string>() : "unknown (run a current bench executable)";
  return flags.is_string() ? name + ", " + widest_vector_isa(flags.get<std::string>()) : name;
}

std::string machine_label(const nlohmann::json& machine) {
  return machine_label(machine.value("cpu", nlohmann::json()), machine.value("cpu_flags", nlohmann::json()));
}

std::string build_options(const nlohmann::json& machine) {
  const nlohmann::json flags = machine.value("flags", nlohmann::json());
  if (!flags.is_string()) return ", build flags not recorded";
  std::istringstream words(flags.get<std::string>());
  std::string options, word;
  while (words >> word)
    if (!word.starts_with("-W")) options += " " + word;
  return options;
}

std::string machine_key(const nlohmann::json& machine) {
  const auto part = [&](const char* key, const char* what) {
    const nlohmann::json value = machine.value(key, nlohmann::json());
    return value.is_string() ? value.get<std::string>() : std::string(what) + " not recorded";
  };
  const nlohmann::json flags = machine.value("cpu_flags", nlohmann::json());
  const std::string isa = flags.is_string() ? widest_vector_isa(flags.get<std::string>()) : "CPU flags not recorded";
  return part("cpu", "CPU") + ", " + isa + ", " + part("compiler", "compiler") + build_options(machine);
}

}  // namespace affinterp::bench
