#include "experiments/claims/claim.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "experiments/claims/sym3/sd_sweep.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::claims::sym3::thesis_sd_case3 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.sd.case3",
    .chapter = Chapter::sym3,
    .where = "thesis §3.1.2",
    .statement = "With distinct eigenvalues, the printed x = s + t + u, y, z (and s, t, u) give exp S = xS² + yS + zI.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: distinct eigenvalues λ1, λ2, λ3 in the order given; y, z, s, t, u as printed. t and u as printed are minus
//   the Lagrange coefficients e^{λ2}/((λ2−λ1)(λ2−λ3)) and e^{λ3}/((λ3−λ1)(λ3−λ2)); the printed y and z account for
//   that sign, the printed x = s + t + u does not, so x = s − t − u is tested as the correction.
// Method: both readings at 100 digits on the same rational S = Q diag(λ) Qᵀ (sd_sweep.hpp); the counterexample is the
//   smallest integer spectrum with Q = E (by max |λ|, then Σ|λ|) where the printed x fails.
//   Proof for all distinct real eigenvalues (proof()): xλ² + yλ + z = e^λ at λ1, λ2, λ3 with the corrected x (rational
//   identities, e^{λi} independent variables), and not with the printed x.
// Sizes: quick 20 matrices; full 200.

using affinterp::sym3::SdReading;
using exact::Real100;

/// The proof for all distinct real λ1, λ2, λ3: with theory/sym3's case-3 coefficients over symbols, xλi² + yλi + z =
/// e^{λi} for i = 1, 2, 3 (rational identities in λ and the values e^{λi}, which the grid reads as independent
/// variables) with the corrected x, and not with the printed one. With S = Q diag(λ) Qᵀ (spectral theorem) the
/// interpolation gives xS² + yS + zE = Q diag(e^λ) Qᵀ = exp S.
Proof proof(const ClaimContext& ctx) {
  const std::array<GiNaC::symbol, 3> l{GiNaC::symbol("l1"), GiNaC::symbol("l2"), GiNaC::symbol("l3")};
  const GiNaC::symbol lambda("lambda");
  std::vector<proofs::Identity> identities;
  for (const SdReading reading : {SdReading::corrected, SdReading::printed}) {
    const std::string name = reading == SdReading::corrected ? "corrected" : "printed";
    const auto c = affinterp::sym3::sd_case3<GiNaC::ex>(l[0], l[1], l[2], reading);
    const GiNaC::ex p = c.x * lambda * lambda + c.y * lambda + c.z;  // p(λ), substituted by the checkers
    for (int i = 0; i < 3; ++i) {
      const std::string at = "l" + std::to_string(i + 1);
      identities.push_back({name + ".interpolates-at-" + at,
                            "x " + at + "² + y " + at + " + z = exp(" + at +
                                ") with x = " + (reading == SdReading::corrected ? "s − t − u" : "s + t + u (printed)"),
                            proofs::substitution(p, lambda, l[i]), GiNaC::exp(l[i])});
    }
  }
  return proofs::identity_proof(
      "all distinct real eigenvalues λ1, λ2, λ3",
      "rational identities in λ1, λ2, λ3 and e^λ1, e^λ2, e^λ3 (independent variables on the grid) from theory/sym3's "
      "case 3 over symbols: the corrected x interpolates exp at the eigenvalues, the printed x does not; exp S = "
      "xS² + yS + zE follows by the spectral theorem (Lemma L20)",
      proofs::prove_identities(identities, ctx.proof_files()));
}

/// Case 3 of thesis §3.1.2 in either reading, as a function of the eigenvalues.
auto with_reading(SdReading reading) {
  return [reading](const Real100& l1, const Real100& l2, const Real100& l3) {
    return affinterp::sym3::sd_case3(l1, l2, l3, reading);
  };
}

/// The smallest counterexample to the printed form: integer spectra with Q = E, by max |λ| then Σ|λ|.
std::optional<Trial> smallest_printed_failure() {
  for (int bound = 1; bound <= 3; ++bound)
    for (int a = -bound; a <= bound; ++a)
      for (int b = a + 1; b <= bound; ++b)
        for (int c = b + 1; c <= bound; ++c) {
          const Trial t = run(with_exact_eigenvalues(Vec3Q(Rational(a), Rational(b), Rational(c)), Vec3Q::Zero()),
                              with_reading(SdReading::printed));
          if (t.deviation > Real100(kResolution)) return t;
        }
  return std::nullopt;
}

/// The symbolic proof must say what the sweep says: the corrected x proved (its first three sentences zero), the
/// printed x failing (the rest non-zero).
void require_proof_agrees(const Proof& proof, const Sweep& printed, const Sweep& corrected) {
  const auto& sentences = proof.sentences;
  const bool corrected_proved =
      std::all_of(sentences.begin(), sentences.begin() + 3, [](const auto& s) { return s.result == "zero"; });
  const bool printed_fails =
      std::all_of(sentences.begin() + 3, sentences.end(), [](const auto& s) { return s.result == "non-zero"; });
  if (corrected_proved != (corrected.failures == 0) || printed_fails != (printed.failures > 0))
    throw std::runtime_error("the proof of case 3 disagrees with the 100-digit sweep");
}

/// The verdict from both readings' sweeps: confirmed as printed, corrected by x = s − t − u, or refuted; with the
/// smallest failing spectrum and both readings' x there.
void decide(Outcome& out, const Sweep& printed, const Sweep& corrected) {
  const std::string correction = "x = s − t − u (y, z, s, t, u as printed)";
  if (printed.failures == 0) {
    out.verdict = Verdict::confirmed;
    out.summary = "case 3 as printed gives exp S on every sample";
  } else if (corrected.failures == 0) {
    out.verdict = Verdict::corrected;
    out.summary = "case 3 as printed (x = s + t + u) is wrong on " + std::to_string(printed.failures) + " of " +
                  std::to_string(printed.samples) + " rational S; with " + correction +
                  " it gives exp S to 100 digits on all";
    out.correction = correction;
  } else {
    out.verdict = Verdict::refuted;
    out.summary = "case 3 is wrong as printed and with x = s − t − u";
  }
  if (out.verdict == Verdict::confirmed) return;
  const std::optional<Trial> smallest = smallest_printed_failure();
  const Trial& t = smallest ? *smallest : *printed.first_failure;
  out.counterexample = counterexample_json(t);
  const Real100 l1(t.spectrum.lambda(0)), l2(t.spectrum.lambda(1)), l3(t.spectrum.lambda(2));
  out.counterexample["x_printed"] = static_cast<double>(affinterp::sym3::sd_case3(l1, l2, l3, SdReading::printed).x);
  out.counterexample["x_corrected"] =
      static_cast<double>(affinterp::sym3::sd_case3(l1, l2, l3, SdReading::corrected).x);
  out.counterexample["labelling"] = "λ1, λ2, λ3 = lambda in the order given";
}

Outcome check(const ClaimContext& ctx) {
  auto distinct = [](Rng& r) {
    Vec3Q l(eigenvalue(r), eigenvalue(r), eigenvalue(r));
    while (l(1) == l(0)) l(1) = eigenvalue(r);
    while (l(2) == l(0) || l(2) == l(1)) l(2) = eigenvalue(r);
    return l;
  };
  const int samples = ctx.pick(20, 200);
  Rng printed_rng(ctx.seed), corrected_rng(ctx.seed);  // the same matrices for both readings
  const Sweep printed = sweep(printed_rng, samples, distinct, with_reading(SdReading::printed));
  const Sweep corrected = sweep(corrected_rng, samples, distinct, with_reading(SdReading::corrected));

  Outcome out;
  out.proof = proof(ctx);
  require_proof_agrees(*out.proof, printed, corrected);
  out.evidence.method =
      "100-digit evaluation of xS² + yS + zE, x as printed (s + t + u) and corrected (s − t − u), "
      "on rational S = Q diag(λ) Qᵀ (distinct exact λ, exact Cayley Q) against Q diag(e^λ) Qᵀ";
  out.evidence.sample_size = static_cast<std::uint64_t>(samples);
  out.evidence.seed = ctx.seed;
  out.evidence.tolerance = std::stod(kResolution);
  out.evidence.worst_deviation = static_cast<double>(corrected.worst);
  out.evidence.details = {
      {"printed_failures", std::to_string(printed.failures) + " of " + std::to_string(printed.samples)},
      {"printed_worst_deviation", static_cast<double>(printed.worst)},
      {"corrected_failures", std::to_string(corrected.failures) + " of " + std::to_string(corrected.samples)},
      {"corrected_worst_deviation", static_cast<double>(corrected.worst)},
      {"taylor_reference_max_disagreement", static_cast<double>(corrected.worst_reference_disagreement)},
      {"why",
       "t and u as printed are minus the Lagrange coefficients e^{λ2}/((λ2−λ1)(λ2−λ3)) and "
       "e^{λ3}/((λ3−λ1)(λ3−λ2)); the printed y and z account for that sign, the printed x does not"}};
  decide(out, printed, corrected);
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sym3::thesis_sd_case3
