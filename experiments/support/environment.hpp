#pragma once
// The machine and toolchain a run happened on, for the report's reproduction section.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp {

/// compiler, flags, CPU model, core count, OS, and the versions of Eigen, Boost, nlohmann_json and gnuplot.
nlohmann::json environment_description();

/// The CPU's feature flags as the kernel lists them (/proc/cpuinfo "flags"), or "unknown": with the CPU model they
/// tell machines apart that share a model name (vector extensions, FMA).
std::string cpu_flags();

}  // namespace affinterp
