#include "theory/origin/energy.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/printed_section_2_3.hpp"
#include "theory/origin/symbols.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checks/origin/rational_gen.hpp"

#include <stdexcept>

namespace energy_test {

using namespace affinterp::origin;
using affinterp::origin::testing::origin_substitution;

TEST(Minimise, SolvesASmallQuadraticExactly) {
  const GiNaC::symbol a("a"), b("b"), s("s");
  // (a − 1)² + (a + b − s)² + b²: minimiser a = (s + 2)/3, b = (s − 1)/3 (by hand).
  const GiNaC::ex E = GiNaC::pow(a - 1, 2) + GiNaC::pow(a + b - s, 2) + b * b;
  const Minimum m = minimise(E, GiNaC::lst{a, b});
  EXPECT_TRUE((GiNaC::ex(a).subs(m.minimiser) - (s + 2) / 3).normal().is_zero());
  EXPECT_TRUE((GiNaC::ex(b).subs(m.minimiser) - (s - 1) / 3).normal().is_zero());
  EXPECT_TRUE((m.value - E.subs(m.minimiser)).normal().is_zero());
}

TEST(Minimise, RejectsNonQuadraticAndSingularEnergies) {
  const GiNaC::symbol a("a"), b("b");
  EXPECT_THROW(minimise(a * a * b * b, GiNaC::lst{a, b}), std::invalid_argument);
  EXPECT_THROW(minimise(GiNaC::pow(a + b, 2), GiNaC::lst{a, b}), std::invalid_argument);
}

TEST(Minimise, RejectsTheEnergyWithB2AsPrinted) {
  // With b21, b22 read literally (a product v4x·x·v3x) E2 is not quadratic in the vertices.
  const GiNaC::ex E = energy_E1(printed::A1(), printed::A2(), printed::B1(), printed::B2(printed::Reading::as_printed));
  EXPECT_THROW(minimise(E, symbols().unknowns), std::invalid_argument);
}

TEST(OriginStudy, SymbolicMinimiserSolvesTheNormalEquationsExactly) {
  for (const GiNaC::ex& equation : normal_equations(thesis_study().E2_common, symbols().unknowns))
    EXPECT_TRUE(equation.lhs().subs(thesis_study().min_E2_common.minimiser).normal().is_zero()) << equation;
}

TEST(OriginStudy, EnergyE1IsE2WithBothOriginsAtZero) {
  EXPECT_TRUE((thesis_study().E2_common.subs(origin_substitution(0, 0)) - thesis_study().E1).expand().is_zero());
  EXPECT_TRUE(
      (thesis_study().min_E2_common.value.subs(origin_substitution(0, 0)) - thesis_study().min_E1.value).is_zero());
}

RC_GTEST_PROP(OriginStudy, MinimiserAtARationalOriginSatisfiesTheNormalEquations,
              (GiNaC::numeric x, GiNaC::numeric y)) {
  const GiNaC::lst o = origin_substitution(x, y);
  const GiNaC::ex E = thesis_study().E2_common.subs(o);
  const Minimum m = minimise(E, symbols().unknowns);
  for (const GiNaC::ex& equation : normal_equations(E, symbols().unknowns))
    RC_ASSERT(equation.lhs().subs(m.minimiser).is_zero());
  // The symbolic minimiser, evaluated at o, is the same point.
  for (const GiNaC::ex& relation : m.minimiser)
    RC_ASSERT((relation.rhs() - relation.lhs().subs(thesis_study().min_E2_common.minimiser).subs(o)).is_zero());
}

RC_GTEST_PROP(OriginStudy, TheStationaryPointIsTheMinimum,
              (GiNaC::numeric x, GiNaC::numeric y, unsigned direction, GiNaC::numeric step)) {
  RC_PRE(!step.is_zero());
  // E is quadratic: E(v* + s e) − E(v*) = s² e^T H e / 2, positive for a positive definite Hessian.
  const GiNaC::lst o = origin_substitution(x, y);
  const GiNaC::ex E = thesis_study().E2_common.subs(o);
  const Minimum m = minimise(E, symbols().unknowns);
  GiNaC::lst moved;
  for (unsigned k = 0; k < m.minimiser.nops(); ++k) {
    const GiNaC::ex relation = m.minimiser.op(k);
    moved.append(relation.lhs() == relation.rhs() + (k == direction % 8 ? GiNaC::ex(step) : GiNaC::ex(0)));
  }
  RC_ASSERT(GiNaC::ex_to<GiNaC::numeric>(E.subs(moved) - m.value).is_positive());
}

}  // namespace energy_test
