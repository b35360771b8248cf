#pragma once
// The one error type of theory/global.
#include <stdexcept>

namespace affinterp::global {

/// A problem the engine refuses rather than answer with a degenerate animation: invalid input, a
/// minimiser that is not unique, or a minimum that is a collapse. what() names what is missing.
class RefusedProblem : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace affinterp::global
