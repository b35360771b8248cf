#include "theory/global/options.hpp"

#include <stdexcept>

namespace affinterp::global {

std::string to_string(LocalHomotopy homotopy) {
  switch (homotopy) {
    case LocalHomotopy::exp:
      return "exp";
    case LocalHomotopy::polar:
      return "polar";
    case LocalHomotopy::linear:
      return "linear";
    case LocalHomotopy::svd:
      return "svd";
  }
  return "?";
}

std::string to_string(Energy energy) {
  switch (energy) {
    case Energy::F:
      return "F";
    case Energy::S:
      return "S";
    case Energy::R:
      return "R";
    case Energy::blend:
      return "blend";
  }
  return "?";
}

std::string to_string(RotationBranch branch) {
  switch (branch) {
    case RotationBranch::principal:
      return "principal";
    case RotationBranch::consistent:
      return "consistent";
  }
  return "?";
}

LocalHomotopy parse_local_homotopy(const std::string& name) {
  for (auto h : {LocalHomotopy::exp, LocalHomotopy::polar, LocalHomotopy::linear, LocalHomotopy::svd})
    if (to_string(h) == name) return h;
  throw std::invalid_argument("unknown local homotopy '" + name + "' (exp, polar, linear, svd)");
}

Energy parse_energy(const std::string& name) {
  for (auto e : {Energy::F, Energy::S, Energy::R, Energy::blend})
    if (to_string(e) == name) return e;
  throw std::invalid_argument("unknown energy '" + name + "' (F, S, R, blend)");
}

RotationBranch parse_rotation_branch(const std::string& name) {
  for (auto b : {RotationBranch::principal, RotationBranch::consistent})
    if (to_string(b) == name) return b;
  throw std::invalid_argument("unknown rotation branch '" + name + "' (principal, consistent)");
}

}  // namespace affinterp::global
