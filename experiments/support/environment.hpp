#pragma once
// The machine and toolchain a run happened on, for the report's reproduction section.
#include <nlohmann/json.hpp>

namespace affinterp {

/// compiler, flags, CPU model, core count, OS, and the versions of Eigen, Boost, nlohmann_json and gnuplot.
nlohmann::json environment_description();

}  // namespace affinterp
