#include "experiments/proofs/structural.hpp"

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace affinterp::proofs {

namespace {

using logic::Formula;
using logic::Polynomial;
using logic::Relation;

/// A literal: a boolean variable and whether the atom is that variable (true) or its negation (false).
struct Literal {
  int variable = 0;
  bool positive = true;
};

/// Numbers the atoms so that opposite sign conditions on one polynomial share a variable: p op 0 is first
/// brought to a polynomial whose leading term (the map's last) is positive, then to one of <, =, > (positive)
/// or ≥, ≠, ≤ (their negations).
class Atoms {
 public:
  Literal literal(const Polynomial& p, Relation r) {
    Polynomial q = p;
    if (!q.is_zero() && q.terms().rbegin()->second < 0) {
      q = -q;
      r = mirrored(r);
    }
    bool positive = r == Relation::less || r == Relation::equal || r == Relation::greater;
    if (!positive) r = logic::negated(r);
    const auto key = std::pair(q, r);
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (keys_[i] == key) return {static_cast<int>(i), positive};
    keys_.push_back(key);
    return {static_cast<int>(keys_.size() - 1), positive};
  }
  int count() const { return static_cast<int>(keys_.size()); }

 private:
  /// The relation of (−p) op' 0 equivalent to p op 0.
  static Relation mirrored(Relation r) {
    switch (r) {
      case Relation::less:
        return Relation::greater;
      case Relation::less_equal:
        return Relation::greater_equal;
      case Relation::greater:
        return Relation::less;
      case Relation::greater_equal:
        return Relation::less_equal;
      default:
        return r;
    }
  }
  std::vector<std::pair<Polynomial, Relation>> keys_;
};

/// The propositional skeleton: atoms replaced by literals, quantifiers dropped, negations kept.
struct Skeleton {
  Formula::Kind kind = Formula::Kind::constant;
  bool value = true;
  Literal literal;
  std::vector<Skeleton> parts;
};

Skeleton skeleton(const Formula& f, Atoms& atoms) {
  Skeleton s{f.kind, f.value, {}, {}};
  switch (f.kind) {
    case Formula::Kind::atom:
      s.literal = atoms.literal(f.polynomial, f.relation);
      break;
    case Formula::Kind::exists:
    case Formula::Kind::forall:
      return skeleton(f.parts.front(), atoms);
    default:
      for (const Formula& part : f.parts) s.parts.push_back(skeleton(part, atoms));
  }
  return s;
}

/// Three-valued evaluation under a partial assignment (nullopt: not yet decided).
std::optional<bool> evaluate(const Skeleton& s, const std::vector<std::optional<bool>>& assignment) {
  switch (s.kind) {
    case Formula::Kind::constant:
      return s.value;
    case Formula::Kind::atom: {
      const std::optional<bool> v = assignment[static_cast<std::size_t>(s.literal.variable)];
      return v ? std::optional(*v == s.literal.positive) : std::nullopt;
    }
    case Formula::Kind::negation: {
      const std::optional<bool> v = evaluate(s.parts.front(), assignment);
      return v ? std::optional(!*v) : std::nullopt;
    }
    case Formula::Kind::conjunction:
    case Formula::Kind::disjunction: {
      const bool conjunction = s.kind == Formula::Kind::conjunction;
      bool open = false;
      for (const Skeleton& part : s.parts) {
        const std::optional<bool> v = evaluate(part, assignment);
        if (!v)
          open = true;
        else if (*v != conjunction)
          return !conjunction;  // a false conjunct, a true disjunct
      }
      return open ? std::nullopt : std::optional(conjunction);
    }
    default:
      return std::nullopt;
  }
}

/// Backtracking over the variables in order, pruned as soon as the skeleton is decided.
bool satisfiable(const Skeleton& s, std::vector<std::optional<bool>>& assignment, std::size_t next) {
  if (const std::optional<bool> v = evaluate(s, assignment)) return *v;
  if (next == assignment.size()) return false;
  for (const bool value : {true, false}) {
    assignment[next] = value;
    if (satisfiable(s, assignment, next + 1)) return true;
  }
  assignment[next].reset();
  return false;
}

}  // namespace

bool is_structural(const Formula& sentence) {
  Atoms atoms;
  const Skeleton s = skeleton(sentence, atoms);
  std::vector<std::optional<bool>> assignment(static_cast<std::size_t>(atoms.count()));
  return !satisfiable(s, assignment, 0);
}

}  // namespace affinterp::proofs
