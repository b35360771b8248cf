#include "experiments/proofs/ginac_polynomial.hpp"

#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {

std::string text_of(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
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
