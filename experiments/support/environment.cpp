#include "experiments/support/environment.hpp"

#include <Eigen/Core>
#include <boost/version.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

namespace affinterp {

namespace {

/// The value of the first line of `file` that starts with `key`, after the separator.
std::string field_of(const char* file, const std::string& key, char separator) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    auto value = line.substr(line.find(separator) + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    value.erase(value.find_last_not_of(" \t\"") + 1);
    return value;
  }
  return "unknown";
}

std::string first_line_of_command(const char* command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command, "r"), pclose);
  if (!pipe) return "unknown";
  std::array<char, 256> buffer{};
  if (fgets(buffer.data(), buffer.size(), pipe.get()) == nullptr) return "unknown";
  std::string line = buffer.data();
  line.erase(line.find_last_not_of("\r\n") + 1);
  return line;
}

}  // namespace

std::string cpu_flags() { return field_of("/proc/cpuinfo", "flags", ':'); }

std::string loaded_blas() {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    const std::size_t path = line.find('/');
    if (path != std::string::npos && line.find("libblas.so", path) != std::string::npos) return line.substr(path);
  }
  return "none loaded";
}

nlohmann::json environment_description() {
  return {
      {"compiler", std::string("g++ ") + __VERSION__},
      {"flags", AFFINTERP_CXX_FLAGS},
      {"build_type", AFFINTERP_BUILD_TYPE},
      {"cpu", field_of("/proc/cpuinfo", "model name", ':')},
      {"hardware_threads", std::thread::hardware_concurrency()},
      {"os", field_of("/etc/os-release", "PRETTY_NAME", '=')},
      {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                    std::to_string(EIGEN_MINOR_VERSION)},
      {"boost", std::to_string(BOOST_VERSION / 100000) + "." + std::to_string(BOOST_VERSION / 100 % 1000) + "." +
                    std::to_string(BOOST_VERSION % 100)},
      {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
      {"gnuplot", first_line_of_command("gnuplot --version 2>/dev/null")},
      {"blas", loaded_blas()},
  };
}

}  // namespace affinterp
