#pragma once
// The algebraic claims of thesis chapter 3, decided exactly (rationals) or at 100 digits on rational
// matrices with exactly known eigenvalues.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

namespace affinterp::claims::sym3 {

/// Resolution of the 100-digit comparisons: deviations below this are rounding, above it a failure.
inline constexpr const char* kResolution = "1e-80";

Outcome check_charpoly(const RunContext& ctx);  ///< thesis.eq-3.charpoly (§3.2)
Outcome check_viete(const RunContext& ctx);     ///< thesis.viete (§3.2)
Outcome check_sd_case1(const RunContext& ctx);  ///< thesis.sd.case1 (§3.1.2)
Outcome check_sd_case2(const RunContext& ctx);  ///< thesis.sd.case2 (§3.1.2)
Outcome check_sd_case3(const RunContext& ctx);  ///< thesis.sd.case3 (§3.1.2)

}  // namespace affinterp::claims::sym3
