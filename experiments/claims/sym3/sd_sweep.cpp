#include "experiments/claims/sym3/sd_sweep.hpp"

#include "experiments/claims/values.hpp"

#include <algorithm>

namespace affinterp::claims::sym3 {

using affinterp::sym3::Mat3R100;
using exact::Real100;

namespace {

nlohmann::json spectrum_json(const ExactSpectrum& e) {
  return {exact::to_string(e.lambda(0)), exact::to_string(e.lambda(1)), exact::to_string(e.lambda(2))};
}

}  // namespace

Trial run(const ExactSpectrum& e, const Coefficients& coefficients) {
  const Mat3R100 S = affinterp::sym3::to_real100(e.S);
  const auto c = coefficients(Real100(e.lambda(0)), Real100(e.lambda(1)), Real100(e.lambda(2)));
  Trial t{e, affinterp::sym3::sd_polynomial(S, c), exact_exp(e), 0};
  t.deviation = relative_deviation(t.formula, t.truth);
  return t;
}

Sweep sweep(Rng& rng, int samples, const std::function<Vec3Q(Rng&)>& spectrum, const Coefficients& coefficients) {
  Sweep s;
  const Real100 resolution(kResolution);
  for (int i = 0; i < samples; ++i, ++s.samples) {
    const Trial t = run(with_exact_eigenvalues(spectrum(rng), small_axis(rng)), coefficients);
    s.worst = std::max(s.worst, t.deviation);
    const Mat3R100 taylor = affinterp::sym3::exp_by_taylor(affinterp::sym3::to_real100(t.spectrum.S));
    s.worst_reference_disagreement = std::max(s.worst_reference_disagreement, relative_deviation(taylor, t.truth));
    if (t.deviation > resolution) {
      ++s.failures;
      if (!s.first_failure) s.first_failure = t;
    }
  }
  return s;
}

nlohmann::json counterexample_json(const Trial& t) {
  return {{"S", exact_matrix(t.spectrum.S)},
          {"lambda", spectrum_json(t.spectrum)},
          {"printed_exp_S", float_matrix(t.formula)},
          {"true_exp_S", float_matrix(t.truth)},
          {"relative_deviation", static_cast<double>(t.deviation)}};
}

Outcome confirmed_or_refuted(const ClaimContext& ctx, const Sweep& s, const std::string& what,
                             const std::string& spectra) {
  Outcome out;
  out.evidence.method =
      "100-digit evaluation of the printed xS² + yS + zE on rational S = Q diag(λ) Qᵀ (exact λ, "
      "exact Cayley Q) against Q diag(e^λ) Qᵀ";
  out.evidence.sample_size = static_cast<std::uint64_t>(s.samples);
  out.evidence.seed = ctx.seed;
  out.evidence.tolerance = std::stod(kResolution);
  out.evidence.worst_deviation = static_cast<double>(s.worst);
  out.evidence.details = {{"spectra", spectra},
                          {"taylor_reference_max_disagreement", static_cast<double>(s.worst_reference_disagreement)}};
  if (s.failures == 0) {
    out.verdict = Verdict::confirmed;
    out.summary = what + " gives exp S to 100 digits on " + std::to_string(s.samples) + " rational S (" +
                  std::string(ctx.claim_id) + ")";
  } else {
    out.verdict = Verdict::refuted;
    out.summary =
        what + " misses exp S on " + std::to_string(s.failures) + " of " + std::to_string(s.samples) + " rational S";
    out.counterexample = counterexample_json(*s.first_failure);
  }
  return out;
}

Rational eigenvalue(Rng& rng) { return small_rational(rng, 12, 4); }

}  // namespace affinterp::claims::sym3
