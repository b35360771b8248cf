#pragma once
// The machine and toolchain a run happened on, for the report's reproduction section.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp {

/// compiler, flags, CPU model, core count, OS, the versions of Eigen, Boost, nlohmann_json and gnuplot, and the
/// BLAS this process loaded (CHOLMOD's).
nlohmann::json environment_description();

/// The CPU's feature flags as the kernel lists them (/proc/cpuinfo "flags"), or "unknown": with the CPU model they
/// tell machines apart that share a model name (vector extensions, FMA).
std::string cpu_flags();

/// The file of the BLAS loaded into this process (the libblas.so.3 alternative that CHOLMOD links, e.g.
/// /usr/lib/x86_64-linux-gnu/openblas-serial/libblas.so.3), or "none loaded".
std::string loaded_blas();

}  // namespace affinterp
