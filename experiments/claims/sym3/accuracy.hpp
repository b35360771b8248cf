#pragma once
// thesis.exp.accuracy (thesis §3.4): the accuracy of every 3×3 symmetric exponential against a
// 50-digit reference, on every test-matrix family, with the error-versus-gap figure.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

namespace affinterp::claims::sym3 {

/// The thesis's statement: with eigenvalues closer than 10⁻⁶ treated as equal, the improved spectral
/// decomposition has error below 10⁻⁶ for eigenvalues in [0, 3].
inline constexpr double kThesisErrorBound = 1e-6;
/// The suite's own target: relative error ≤ 2·10⁻¹⁵·max(1, ‖S‖₂) on every matrix.
inline constexpr double kOwnTarget = 2e-15;

Outcome check_exp_accuracy(const RunContext& ctx);

}  // namespace affinterp::claims::sym3
