#include "theory/origin/energy.hpp"

#include "theory/origin/affine_frames.hpp"

#include <stdexcept>

namespace affinterp::origin {

GiNaC::ex frobenius_squared(const GiNaC::matrix& M) {
  GiNaC::ex sum = 0;
  for (unsigned r = 0; r < M.rows(); ++r)
    for (unsigned c = 0; c < M.cols(); ++c) sum += GiNaC::pow(M(r, c), 2);
  return sum;
}

GiNaC::ex energy_E1(const GiNaC::matrix& A1, const GiNaC::matrix& A2, const GiNaC::matrix& B1,
                    const GiNaC::matrix& B2) {
  return frobenius_squared(A1.sub(B1)) + frobenius_squared(A2.sub(B2));
}

GiNaC::ex energy_E2(const GiNaC::matrix& A1, const GiNaC::matrix& A2, const GiNaC::matrix& B1, const GiNaC::matrix& B2,
                    const GiNaC::matrix& o1, const GiNaC::matrix& o2) {
  const GiNaC::matrix minus_o1 = o1.mul_scalar(-1), minus_o2 = o2.mul_scalar(-1);
  return energy_E1(translate_origin(A1, minus_o1), translate_origin(A2, minus_o2), translate_origin(B1, minus_o1),
                   translate_origin(B2, minus_o2));
}

GiNaC::lst normal_equations(const GiNaC::ex& energy, const GiNaC::lst& unknowns) {
  GiNaC::lst equations;
  for (const GiNaC::ex& u : unknowns)
    equations.append(GiNaC::diff(energy, GiNaC::ex_to<GiNaC::symbol>(u)).expand() == 0);
  return equations;
}

Minimum minimise(const GiNaC::ex& energy, const GiNaC::lst& unknowns) {
  const GiNaC::ex expanded = energy.expand();
  // Total degree in the unknowns: scale them all by one symbol and read its degree.
  const GiNaC::symbol scale("scale");
  GiNaC::exmap scaled;
  for (const GiNaC::ex& u : unknowns) scaled[u] = scale * u;
  if (expanded.subs(scaled).expand().degree(scale) > 2)
    throw std::invalid_argument("minimise: the energy is not quadratic in the unknowns");
  const GiNaC::ex solution = GiNaC::lsolve(normal_equations(expanded, unknowns), unknowns);
  bool determined = solution.nops() == unknowns.nops();
  for (const GiNaC::ex& relation : solution)
    for (const GiNaC::ex& u : unknowns) determined = determined && !relation.rhs().has(u);
  if (!determined) throw std::invalid_argument("minimise: the normal equations are singular");
  Minimum m;
  for (const GiNaC::ex& relation : solution) m.minimiser.append(relation.lhs() == relation.rhs().normal());
  m.value = expanded.subs(m.minimiser).normal();
  return m;
}

}  // namespace affinterp::origin
