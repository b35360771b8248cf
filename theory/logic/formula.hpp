#pragma once
// First-order formulas over the reals whose atoms are polynomial sign conditions `p op 0`: the
// language of the sentences that QEPCAD B and Z3 decide. A Formula is a plain value tree; the functions
// below evaluate quantifier-free formulas exactly and bring sentences into the prenex form the deciders read.
#include "theory/logic/polynomial.hpp"

#include <set>
#include <string>
#include <vector>

namespace affinterp::logic {

enum class Relation { less, less_equal, greater, greater_equal, equal, not_equal };

/// The relation of ¬(p op 0), e.g. < ↦ ≥.
Relation negated(Relation r);
/// value op 0.
bool compare(const Rational& value, Relation r);
/// "<", "<=", ">", ">=", "=", "!=".
std::string_view symbol(Relation r);

struct Formula {
  enum class Kind { constant, atom, conjunction, disjunction, negation, exists, forall };
  Kind kind = Kind::constant;
  bool value = true;                    ///< constant
  Polynomial polynomial;                ///< atom: polynomial op 0
  Relation relation = Relation::equal;  ///< atom
  std::vector<Formula> parts;           ///< conjunction, disjunction (any number); negation, quantifier (one)
  std::vector<std::string> bound;       ///< the quantified variables, in order
};

Formula truth(bool value);
Formula atom(const Polynomial& p, Relation r);
Formula conjunction(std::vector<Formula> parts);  ///< true when empty
Formula disjunction(std::vector<Formula> parts);  ///< false when empty
Formula negation(Formula f);
Formula exists(std::vector<std::string> variables, Formula f);
Formula forall(std::vector<std::string> variables, Formula f);
inline Formula operator&&(Formula a, Formula b) { return conjunction({std::move(a), std::move(b)}); }
inline Formula operator||(Formula a, Formula b) { return disjunction({std::move(a), std::move(b)}); }
inline Formula operator!(Formula f) { return negation(std::move(f)); }
inline Formula implies(Formula a, Formula b) { return !std::move(a) || std::move(b); }

// a op b as the atom (a − b) op 0.
Formula less(const Polynomial& a, const Polynomial& b);
Formula less_equal(const Polynomial& a, const Polynomial& b);
Formula greater(const Polynomial& a, const Polynomial& b);
Formula greater_equal(const Polynomial& a, const Polynomial& b);
Formula equal(const Polynomial& a, const Polynomial& b);
Formula not_equal(const Polynomial& a, const Polynomial& b);

/// Whether the quantifier-free `f` holds at `at`, exactly; throws std::invalid_argument on a quantifier or a
/// variable without a coordinate.
bool holds(const Formula& f, const Point& at);

std::set<std::string> free_variables(const Formula& f);
/// `f` with the variable `name` replaced by `by` in every atom (a change of coordinates; `name` must not be
/// bound in `f`, and `by`'s variables must not be bound either).
Formula substitute(const Formula& f, const std::string& name, const Polynomial& by);
bool is_quantifier_free(const Formula& f);

/// Constant atoms evaluated, true/false absorbed, nested conjunctions (disjunctions) flattened.
Formula simplify_constants(const Formula& f);
/// Negations pushed into the atoms (the relation flipped) and through quantifiers (∃ ↔ ∀).
Formula negation_normal_form(const Formula& f);
/// Every bound variable given a name used nowhere else (neither free nor bound twice), so that quantifiers
/// can be pulled out; `taken` adds names to avoid.
Formula rename_apart(const Formula& f, const std::set<std::string>& taken = {});

struct QuantifierBlock {
  bool universal = false;
  std::vector<std::string> variables;
};

/// Q1 x1 … Qn xn. matrix, with the matrix quantifier-free.
struct Prenex {
  std::vector<QuantifierBlock> prefix;
  Formula matrix;
  /// No universal block: ∃ x. matrix (or quantifier-free).
  bool existential() const;
  std::vector<std::string> bound_variables() const;
};

/// The prenex form of `f`: negation normal form, constants simplified, renamed apart, then quantifiers pulled
/// out merging blocks of the same kind across conjuncts and disjuncts, existential blocks first (as few
/// alternations as the parts' own prefixes allow). Equivalent to `f` (prenex rules of classical logic over
/// the non-empty domain R).
Prenex prenex(const Formula& f);

}  // namespace affinterp::logic
