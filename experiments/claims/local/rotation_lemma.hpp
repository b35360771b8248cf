#pragma once
// The trigonometric facts that turn identities between rotations R_θ (theory/local/rotation.hpp over symbolic
// angles) into rational identities the identity prover decides: the addition formulas
//   cos(a + b) = cos a cos b − sin a sin b,   sin(a + b) = sin a cos b + cos a sin b,
// then, for every angle symbol u, the tangent half-angle parametrisation of the unit circle
//   cos u = (1 − w²)/(1 + w²),   sin u = 2w/(1 + w²),   w = tan(u/2) a fresh symbol "tan_half_<u>".
// The parametrisation misses only u = π (mod 2π); after the addition formulas both sides are polynomials in
// cos u, sin u, so an identity on the circle minus that point holds on the whole circle (continuity).
#include <ginac/ginac.h>

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace affinterp::claims::local {

/// Applied to an expression or a GiNaC::matrix (entry by entry); one lemma names each angle's w once.
class RotationLemma : public GiNaC::map_function {
 public:
  /// `e` with every cos and sin of a sum of angle symbols written by the addition formulas and the half-angle
  /// parametrisation; throws std::invalid_argument on an angle that is not a sum of ± symbols.
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) return cos_sin(e.op(0)).first;
    if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e)) return cos_sin(e.op(0)).second;
    return e.map(*this);
  }

 private:
  std::map<std::string, GiNaC::symbol> tan_half_;

  std::pair<GiNaC::ex, GiNaC::ex> cos_sin(const GiNaC::ex& angle) {
    if (GiNaC::is_a<GiNaC::add>(angle)) {  // the addition formulas, one term at a time
      const auto [c1, s1] = cos_sin(angle.op(0));
      const auto [c2, s2] = cos_sin(angle - angle.op(0));
      return {c1 * c2 - s1 * s2, s1 * c2 + c1 * s2};
    }
    if (GiNaC::is_a<GiNaC::mul>(angle) && angle.nops() == 2 && angle.op(1).is_equal(-1)) {
      const auto [c, s] = cos_sin(angle.op(0));
      return {c, -s};
    }
    if (!GiNaC::is_a<GiNaC::symbol>(angle))
      throw std::invalid_argument("rotation lemma: the angle is not a sum of symbols");
    const std::string name = "tan_half_" + GiNaC::ex_to<GiNaC::symbol>(angle).get_name();
    const GiNaC::ex w = tan_half_.try_emplace(name, name).first->second;
    return {(1 - w * w) / (1 + w * w), 2 * w / (1 + w * w)};
  }
};

}  // namespace affinterp::claims::local
