#pragma once
// The sweep that decides a case of the spectral decomposition exp S = xS² + yS + zE (thesis §3.1.2): the
// printed coefficients evaluated at 100 digits on rational S = Q diag(λ) Qᵀ with exact rational λ and exact
// rational orthogonal Q (Cayley), against Q diag(e^λ) Qᵀ, cross-checked with the Taylor reference.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>

namespace affinterp::claims::sym3 {

/// The printed (or corrected) coefficients for a spectrum (λ1, λ2, λ3) labelled as the case requires.
using Coefficients = std::function<affinterp::sym3::SdCoefficients<exact::Real100>(
    const exact::Real100&, const exact::Real100&, const exact::Real100&)>;

/// One S: the formula's exp S, the true one, and their relative deviation.
struct Trial {
  ExactSpectrum spectrum;
  affinterp::sym3::Mat3R100 formula, truth;
  exact::Real100 deviation;
};
Trial run(const ExactSpectrum& e, const Coefficients& coefficients);

/// Every sample's deviation and the Taylor cross-check for one printed case.
struct Sweep {
  int samples = 0, failures = 0;
  exact::Real100 worst = 0, worst_reference_disagreement = 0;
  std::optional<Trial> first_failure;
};
/// Runs `samples` spectra drawn by `spectrum`, each in a random Cayley basis (small_axis); a deviation above
/// kResolution is a failure.
Sweep sweep(Rng& rng, int samples, const std::function<Vec3Q(Rng&)>& spectrum, const Coefficients& coefficients);

/// A failing S for claims.json: S, λ, the formula's and the true exp S, the deviation.
nlohmann::json counterexample_json(const Trial& t);

/// The outcome of a case decided by one sweep: confirmed when every sample gives exp S to 100 digits, else refuted
/// with the first failure; `what` names the case and its coefficients, `spectra` says how λ was drawn.
Outcome confirmed_or_refuted(const ClaimContext& ctx, const Sweep& s, const std::string& what,
                             const std::string& spectra);

/// An eigenvalue p/q with |p| ≤ 12, q ≤ 4.
Rational eigenvalue(Rng& rng);

}  // namespace affinterp::claims::sym3
