#pragma once
// The condition grammar of `affinterp decide` , parsed into a quantifier-free Formula:
//
//   condition := disjunct (("or" | "||") disjunct)*
//   disjunct  := literal (("and" | "&&") literal)*
//   literal   := ("not" | "!") literal | "true" | "false" | chain | "(" condition ")"
//   chain     := sum (relation sum)+          a < b <= c means a < b and b <= c
//   relation  := "<" | "<=" | ">" | ">=" | "=" | "==" | "!="
//   sum       := product (("+" | "-") product)*
//   product   := unary (("*" | "/") unary)*
//   unary     := ("-" | "+") unary | power
//   power     := primary ("^" ["-"] INTEGER)?  integer exponents only
//   primary   := INTEGER | DECIMAL | VARIABLE | MACRO | "(" sum ")"      (p/q is a division)
//
// Variables are those the caller lists; macros (tr, det) are polynomials the caller supplies. Division: a
// comparison whose two sides combine to N/D (N, D polynomials, D the product of every denominator met) is
// encoded as D ≠ 0 ∧ N·D op 0, so a comparison is false wherever one of its denominators vanishes.
#include "theory/logic/formula.hpp"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::logic {

/// Parses `text`; throws std::invalid_argument with a one-line message on a syntax error, an unknown
/// variable, a non-integer exponent or a division by the constant zero.
Formula parse_condition(std::string_view text, const std::vector<std::string>& variables,
                        const std::map<std::string, Polynomial>& macros = {});

}  // namespace affinterp::logic
