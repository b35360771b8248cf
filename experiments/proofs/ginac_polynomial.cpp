#include "experiments/proofs/ginac_polynomial.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace affinterp::proofs {

namespace {

/// GiNaC's default text with the operands of every sum and product sorted by their own text: GiNaC orders them by
/// hash values that follow the symbols' creation order in the process, so the same expression printed by two runs
/// that made their symbols in another order would read differently. Everything else prints as print_dflt does, its
/// operands through this context.
using GiNaC::print_dflt;  // unqualified: GiNaC finds a context's parent by the name its macros write down
class CanonicalPrint : public print_dflt {
  GINAC_DECLARE_PRINT_CONTEXT(CanonicalPrint, print_dflt)
 public:
  explicit CanonicalPrint(std::ostream& out) : print_dflt(out) {}
};
CanonicalPrint::CanonicalPrint() : print_dflt(std::cout) {}
GINAC_IMPLEMENT_PRINT_CONTEXT(CanonicalPrint, print_dflt)

// GiNaC's precedences (add.h, mul.h): an operand is parenthesised where the level it is printed at reaches its own.
constexpr unsigned add_precedence = 40, mul_precedence = 50;

std::string canonical_text(const GiNaC::ex& e, unsigned level) {
  std::ostringstream out;
  CanonicalPrint context(out);
  e.print(context, level);
  return out.str();
}

/// Each term at the sum's level, sorted; a term whose text starts with its sign is joined without a '+'.
void print_add(const GiNaC::add& sum, const CanonicalPrint& c, unsigned level) {
  std::vector<std::string> terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    const GiNaC::ex& term = sum.op(i);  // a number as a term needs no parentheses: x-1, not x+(-1)
    terms.push_back(canonical_text(term, GiNaC::is_exactly_a<GiNaC::numeric>(term) ? 0 : add_precedence));
  }
  std::ranges::sort(terms);
  if (level >= add_precedence) c.s << '(';
  for (std::size_t i = 0; i < terms.size(); ++i) c.s << (i > 0 && terms[i].front() != '-' ? "+" : "") << terms[i];
  if (level >= add_precedence) c.s << ')';
}

/// The numeric coefficient first (−1 as a sign), then the other factors sorted, joined by '*'.
void print_mul(const GiNaC::mul& product, const CanonicalPrint& c, unsigned level) {
  GiNaC::numeric coefficient = 1;
  std::vector<std::string> factors;
  for (std::size_t i = 0; i < product.nops(); ++i) {
    if (GiNaC::is_exactly_a<GiNaC::numeric>(product.op(i)))
      coefficient *= GiNaC::ex_to<GiNaC::numeric>(product.op(i));
    else
      factors.push_back(canonical_text(product.op(i), mul_precedence));
  }
  std::ranges::sort(factors);
  if (level >= mul_precedence) c.s << '(';
  if (coefficient.is_negative()) c.s << '-';
  if (abs(coefficient) != 1) factors.insert(factors.begin(), canonical_text(abs(coefficient), mul_precedence));
  for (std::size_t i = 0; i < factors.size(); ++i) c.s << (i > 0 ? "*" : "") << factors[i];
  if (level >= mul_precedence) c.s << ')';
}

const bool canonical_printers = [] {
  GiNaC::set_print_func<GiNaC::add, CanonicalPrint>(print_add);
  GiNaC::set_print_func<GiNaC::mul, CanonicalPrint>(print_mul);
  return true;
}();

}  // namespace

std::string text_of(const GiNaC::ex& e) {
  (void)canonical_printers;
  return canonical_text(e, 0);
}

logic::Polynomial to_polynomial(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_rational()) throw std::invalid_argument("not a rational number: " + text_of(e));
    return logic::Polynomial(exact::parse_rational(text_of(e)));
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) return logic::Polynomial::variable(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    const bool sum = GiNaC::is_a<GiNaC::add>(e);
    logic::Polynomial p = sum ? logic::Polynomial(0) : logic::Polynomial(1);
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (sum)
        p += to_polynomial(e.op(i));
      else
        p *= to_polynomial(e.op(i));
    }
    return p;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const GiNaC::ex exponent = e.op(1);
    if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_nonneg_integer())
      return logic::pow(to_polynomial(e.op(0)), static_cast<unsigned>(GiNaC::ex_to<GiNaC::numeric>(exponent).to_int()));
  }
  throw std::invalid_argument("not a polynomial: " + text_of(e));
}

}  // namespace affinterp::proofs
