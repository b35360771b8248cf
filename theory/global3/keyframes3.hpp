#pragma once
// Frames through K ≥ 2 poses at increasing key times t_0 < … < t_{K−1}: between keys k and k+1 the blend
// (blend3.hpp) with weights (1−s) on pose k and s on pose k+1, s = (t − t_k)/(t_{k+1} − t_k); rest = pose 0,
// one factorisation for all frames.
//
// Continuity: C⁰. At t_k both neighbouring segments give the weights e_k, so the frame is pose k from either
// side; the velocity generally jumps there (each segment is its own blend path). Each segment blends the two
// poses' rest-relative logarithms (exp((1−s)ω_k + sω_{k+1}) …), which is not the exp-log homotopy from pose k to
// pose k+1 (that would take each element's map A_{k+1,i} A_{k,i}⁻¹); both meet the keys.
#include "theory/global3/blend3.hpp"

#include <vector>

namespace affinterp::global3 {

class Keyframes3 {
 public:
  /// Throws global::RefusedProblem for fewer than two poses, a key time count other than the poses', key times
  /// not finite or not strictly increasing, and as Blend3 for the meshes and options (allow_extrapolation is
  /// ignored: the segments' weights lie on the simplex).
  Keyframes3(const std::vector<Mesh3>& poses, std::vector<double> key_times, Blend3Options options = {});

  /// The frame at t ∈ [t_0, t_{K−1}]; throws std::out_of_range elsewhere. Const and thread-safe.
  Eigen::Matrix3Xd vertices_at(double t) const;
  /// One frame per time, in parallel, the same bits as one at a time; all times checked first.
  std::vector<Eigen::Matrix3Xd> vertices_at(const std::vector<double>& times) const;
  /// The blend weights of time t (two adjacent non-zero entries at most).
  Eigen::VectorXd weights_at(double t) const;

  const std::vector<double>& key_times() const { return key_times_; }
  const Blend3& blend() const { return blend_; }

 private:
  std::vector<double> key_times_;
  Blend3 blend_;
};

}  // namespace affinterp::global3
