#pragma once
// Shared by the certified tests: balls against Boost.Multiprecision values.
#include "theory/certified/sym3.hpp"
#include "theory/sym3/reference.hpp"

#include <string>

namespace affinterp::certified::testing {

using exact::Real100;

/// The exact midpoint of a ball at 110 digits, as a Real100.
inline Real100 mid100(const Balls& balls, int i, int j = 0) { return Real100(balls.mid_string(i, j, 110)); }

/// Whether x lies in the ball (i, j) widened by `slack` (the other value's own error bound).
inline bool contains(const Balls& balls, int i, int j, const Real100& x, const Real100& slack) {
  return abs(x - mid100(balls, i, j)) <= Real100(balls.radius(i, j)) + slack;
}

/// Whether the 3×3 balls contain the matrix E, each entry widened by slack.
inline bool contains(const Balls& balls, const sym3::Mat3R100& E, const Real100& slack) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!contains(balls, i, j, E(i, j), slack)) return false;
  return true;
}

inline const char* name(Status status) {
  switch (status) {
    case Status::certified:
      return "certified";
    case Status::overflows:
      return "overflows";
    case Status::not_spd:
      return "not_spd";
    case Status::too_wide:
      return "too_wide";
  }
  return "?";
}

}  // namespace affinterp::certified::testing
