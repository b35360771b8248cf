#pragma once
// The input format of QEPCAD B 1.74 (Brown's partial cylindrical algebraic decomposition): a title, the
// variable list (free variables first, then the quantified ones in prefix order; QEPCAD projects from the
// last one), the number of free variables, the prenex formula with integer coefficients, and commands.
#include "theory/logic/formula.hpp"

#include <string>
#include <vector>

namespace affinterp::logic {

struct QepcadInput {
  std::string title;
  /// Free variables, in the order wanted (none for a sentence).
  std::vector<std::string> free;
  /// Preferred order of the quantified variables inside each block of the prefix (QEPCAD eliminates the
  /// last variable first, and the order can decide whether it finishes); variables not named keep their
  /// prefix order after those named.
  std::vector<std::string> order;
  /// QEPCAD's commands after the formula; empty means the default: for an existential sentence
  /// "go go go d-witness-list finish" (d-witness-list prints the sample point of a true cell, a witness),
  /// otherwise "finish".
  std::vector<std::string> commands;
  /// Commands before `commands` (or the default ones), e.g. "proj-operator (h,h,m)" to choose Hong's projection
  /// where McCallum's, QEPCAD's default, is incomplete (QEPCAD then prints "Error! Delineating polynomial …").
  std::vector<std::string> setup{};
};

/// p with integer coefficients (times the positive lcm of its denominators) in QEPCAD's syntax:
/// multiplication by juxtaposition, "2 x y^2 - 3".
std::string qepcad_polynomial(const Polynomial& p);

/// The QEPCAD B input deciding `f` (a sentence unless `input.free` names its free variables). True and false
/// are simplified away (QEPCAD has no constants; a constant sentence is written as one about a dummy
/// variable zz).
std::string to_qepcad(const Formula& f, const QepcadInput& input);

}  // namespace affinterp::logic
