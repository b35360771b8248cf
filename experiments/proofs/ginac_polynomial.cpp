#include "experiments/proofs/ginac_polynomial.hpp"

#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace affinterp::proofs {

namespace {

/// GiNaC's default text made independent of GiNaC's internal order: the operands of every sum and product sorted by
/// their own text, and every sum that is a factor or an integer power's base given one sign (sign_is_turned). GiNaC
/// orders operands, and picks the sign it stores such a sum with, by hash values seeded with the address of each
/// class's type name (ginac/hash_seed.h), which moves from run to run, so the same expression printed by two runs
/// would read differently. Everything else prints as print_dflt does, its operands through this context.
using GiNaC::print_dflt;  // unqualified: GiNaC finds a context's parent by the name its macros write down
class CanonicalPrint : public print_dflt {
  GINAC_DECLARE_PRINT_CONTEXT(CanonicalPrint, print_dflt)
 public:
  explicit CanonicalPrint(std::ostream& out) : print_dflt(out) {}
};
CanonicalPrint::CanonicalPrint() : print_dflt(std::cout) {}
GINAC_IMPLEMENT_PRINT_CONTEXT(CanonicalPrint, print_dflt)

// GiNaC's precedences (add.h, mul.h, power.h): an operand is parenthesised where the level it is printed at reaches its
// own.
constexpr unsigned add_precedence = 40, mul_precedence = 50, power_precedence = 60;

std::string canonical_text(const GiNaC::ex& e, unsigned level) {
  std::ostringstream out;
  CanonicalPrint context(out);
  e.print(context, level);
  return out.str();
}

/// A sum's term as the sum prints it: at the sum's level, but a number without parentheses (x-1, not x+(-1)).
std::string term_text(const GiNaC::ex& term) {
  return canonical_text(term, GiNaC::is_exactly_a<GiNaC::numeric>(term) ? 0 : add_precedence);
}

/// Each term as term_text writes it, sorted; a term whose text starts with its sign is joined without a '+'.
void print_add(const GiNaC::add& sum, const CanonicalPrint& c, unsigned level) {
  std::vector<std::string> terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) terms.push_back(term_text(sum.op(i)));
  std::ranges::sort(terms);
  if (level >= add_precedence) c.s << '(';
  for (std::size_t i = 0; i < terms.size(); ++i) c.s << (i > 0 && terms[i].front() != '-' ? "+" : "") << terms[i];
  if (level >= add_precedence) c.s << ')';
}

/// Whether `e` is a sum stored with the other sign than the canonical one: the canonical sign makes positive the
/// term whose text, without its sign, comes first.
bool sign_is_turned(const GiNaC::ex& e) {
  if (!GiNaC::is_exactly_a<GiNaC::add>(e)) return false;
  std::string first;
  bool minus = false;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const std::string term = term_text(e.op(i));
    const bool negative = term.front() == '-';
    const std::string key = negative ? term.substr(1) : term;
    if (i == 0 || key < first) first = key, minus = negative;
  }
  return minus;
}

/// The sum with each term negated: GiNaC keeps −s as the product (−1)·s, which would print as s again.
GiNaC::ex negated_terms(const GiNaC::ex& sum) {
  GiNaC::exvector terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) terms.push_back(-sum.op(i));
  return GiNaC::add(terms);
}

/// An integer power of a sum whose sign is turned, s^n, as the text of (−s)^n and the sign (−1)^n that leaves its
/// value alone; nullopt for anything else. Written as text, since GiNaC would turn (−s)^n back into (−1)^n s^n.
std::optional<std::pair<std::string, int>> turned_power(const GiNaC::ex& e) {
  if (!GiNaC::is_exactly_a<GiNaC::power>(e) || !GiNaC::is_a<GiNaC::numeric>(e.op(1)) ||
      !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer() || !sign_is_turned(e.op(0)))
    return std::nullopt;
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
  const std::string exponent = n.is_negative() ? "(" + canonical_text(n, 0) + ")" : canonical_text(n, 0);
  return std::pair{"(" + canonical_text(negated_terms(e.op(0)), 0) + ")^" + exponent, n.is_odd() ? -1 : 1};
}

/// The text of a product's factor with its sum's sign made canonical, and the sign that leaves the product's value
/// alone: s → (−s), −1; s^n → (−s)^n, (−1)^n for an integer n (turned_power); anything else as it is, 1.
std::pair<std::string, int> canonical_factor(const GiNaC::ex& factor) {
  if (sign_is_turned(factor)) return {canonical_text(negated_terms(factor), mul_precedence), -1};
  if (auto power = turned_power(factor)) return *power;
  return {canonical_text(factor, mul_precedence), 1};
}

/// The numeric coefficient first (−1 as a sign), then the other factors with canonical signs, sorted, joined by '*'.
void print_mul(const GiNaC::mul& product, const CanonicalPrint& c, unsigned level) {
  GiNaC::numeric coefficient = 1;
  std::vector<std::string> factors;
  for (std::size_t i = 0; i < product.nops(); ++i) {
    if (GiNaC::is_exactly_a<GiNaC::numeric>(product.op(i))) {
      coefficient *= GiNaC::ex_to<GiNaC::numeric>(product.op(i));
    } else {
      auto [factor, sign] = canonical_factor(product.op(i));
      coefficient *= sign;
      factors.push_back(std::move(factor));
    }
  }
  std::ranges::sort(factors);
  if (level >= mul_precedence) c.s << '(';
  if (coefficient.is_negative()) c.s << '-';
  if (abs(coefficient) != 1) factors.insert(factors.begin(), canonical_text(abs(coefficient), mul_precedence));
  for (std::size_t i = 0; i < factors.size(); ++i) c.s << (i > 0 ? "*" : "") << factors[i];
  if (level >= mul_precedence) c.s << ')';
}

/// A power outside a product: as print_dflt prints it, unless turned_power turns its base's sign (an odd power then
/// printed with a leading '-').
void print_power(const GiNaC::power& p, const CanonicalPrint& c, unsigned level) {
  if (const auto turned = turned_power(p)) {
    const auto& [text, sign] = *turned;
    const bool parenthesised = level >= (sign < 0 ? mul_precedence : power_precedence);
    c.s << (parenthesised ? "(" : "") << (sign < 0 ? "-" : "") << text << (parenthesised ? ")" : "");
    return;
  }
  // GiNaC's own printer of powers for print_dflt, or for print_context where it registered that one instead.
  const auto& dispatch = GiNaC::power::get_class_info_static().options.get_print_dispatch_table();
  const unsigned dflt = print_dflt::get_class_info_static().options.get_id();
  const auto& as_dflt = dflt < dispatch.size() && dispatch[dflt].is_valid()
                            ? dispatch[dflt]
                            : dispatch.at(GiNaC::print_context::get_class_info_static().options.get_id());
  as_dflt(p, c, level);
}

const bool canonical_printers = [] {
  GiNaC::set_print_func<GiNaC::add, CanonicalPrint>(print_add);
  GiNaC::set_print_func<GiNaC::mul, CanonicalPrint>(print_mul);
  GiNaC::set_print_func<GiNaC::power, CanonicalPrint>(print_power);
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
