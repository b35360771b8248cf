#pragma once
// SMT-LIB 2 input for Z3's nonlinear real arithmetic: a sentence whose leading existential block becomes
// declared constants; with nothing else quantified the logic is QF_NRA (complete in Z3's nlsat), otherwise
// NRA with the remaining quantifiers written out.
#include "theory/logic/formula.hpp"

#include <string>

namespace affinterp::logic {

/// p as an SMT-LIB term over Real: (+ (* 2 x y y) (- 3)), rationals as (/ p q).
std::string smtlib_term(const Polynomial& p);

/// The SMT-LIB 2 script deciding the sentence `f`: "; title", set-logic, declarations, assert,
/// (check-sat). No (get-model): it is an error after "unsat", and a transcript with an error decides nothing;
/// the deciders print the model of a satisfiable sentence (a witness) when run with `z3 -model` or
/// `cvc5 --dump-models`.
std::string to_smtlib(const Formula& f, const std::string& title);

}  // namespace affinterp::logic
