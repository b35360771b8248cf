#include "experiments/proofs/expanded_polynomial.hpp"

#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {
namespace {

ExpandedPolynomial constant(const exact::Rational& c) {
  ExpandedPolynomial p;
  if (c != 0) p.terms[{}] = c;
  return p;
}

ExpandedPolynomial sum(const ExpandedPolynomial& a, const ExpandedPolynomial& b) {
  ExpandedPolynomial r = a;
  for (const auto& [monomial, c] : b.terms)
    if ((r.terms[monomial] += c) == 0) r.terms.erase(monomial);
  return r;
}

ExpandedPolynomial product(const ExpandedPolynomial& a, const ExpandedPolynomial& b) {
  ExpandedPolynomial r;
  for (const auto& [ma, ca] : a.terms)
    for (const auto& [mb, cb] : b.terms) {
      std::map<std::string, unsigned> m = ma;
      for (const auto& [name, k] : mb) m[name] += k;
      if ((r.terms[m] += ca * cb) == 0) r.terms.erase(m);
    }
  return r;
}

exact::Rational rational(const GiNaC::numeric& n) {
  if (!n.is_rational()) throw std::invalid_argument("not a rational number");
  std::ostringstream text;
  text << n;
  return exact::parse_rational(text.str());
}

}  // namespace

ExpandedPolynomial expanded(const GiNaC::ex& e, const std::map<std::string, ExpandedPolynomial>& values) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return constant(rational(GiNaC::ex_to<GiNaC::numeric>(e)));
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    if (const auto at = values.find(name); at != values.end()) return at->second;
    ExpandedPolynomial p;
    p.terms[{{name, 1}}] = 1;
    return p;
  }
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    const bool add = GiNaC::is_a<GiNaC::add>(e);
    ExpandedPolynomial r = constant(add ? 0 : 1);
    for (std::size_t i = 0; i < e.nops(); ++i)
      r = add ? sum(r, expanded(e.op(i), values)) : product(r, expanded(e.op(i), values));
    return r;
  }
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_nonneg_integer()) {
    const ExpandedPolynomial base = expanded(e.op(0), values);
    ExpandedPolynomial r = constant(1);
    for (long k = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long(); k > 0; --k) r = product(r, base);
    return r;
  }
  throw std::invalid_argument("not a polynomial");
}

std::string to_text(const ExpandedPolynomial& p) {
  if (p.terms.empty()) return "0";
  std::ostringstream out;
  bool first = true;
  for (const auto& [monomial, c] : p.terms) {
    const bool unit = monomial.empty() ? false : (c == 1 || c == -1);
    out << (c < 0 ? "-" : first ? "" : "+");
    if (!unit) out << exact::to_string(c < 0 ? exact::Rational(-c) : c);
    bool first_factor = unit;
    for (const auto& [name, k] : monomial) {
      out << (first_factor ? "" : "*") << name;
      if (k > 1) out << "^" << k;
      first_factor = false;
    }
    first = false;
  }
  return out.str();
}

}  // namespace affinterp::proofs
