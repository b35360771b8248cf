#pragma once
// The value of the global error function at a frame (Kaji §4): E_t(B) = Σ_i E_i(A_i(t), B_i(t)) + C(v(t)),
// or the symmetrised E′(t) = E(t) + E^{-1}(1 − t) ("Improvements"), split into the parts a user may want to
// weigh against each other. Interpolation::energy_at returns it; the engine minimises `total`.
namespace affinterp::global {

struct FrameEnergy {
  double total = 0.0;  ///< forward + backward + constraints = frobenius + similarity + constraints
  /// Σ_i E_i(A_i(t), B_i(t)) of the problem P → Q, and of the reverse problem Q → P at 1 − t (0 unless
  /// symmetrised), each E_i times its area when area weighted.
  double forward = 0.0, backward = 0.0;
  /// The same local errors split by kind: the E^F part (w_i E^F of a blend, all of E^F) and the rest
  /// ((1 − w_i) E^R of a blend, all of E^R or E^S).
  double frobenius = 0.0, similarity = 0.0;
  double constraints = 0.0;  ///< C(v(t)): Σ c ‖Σ_k α_k v_k − r(t)‖² over the constraint terms
};

}  // namespace affinterp::global
