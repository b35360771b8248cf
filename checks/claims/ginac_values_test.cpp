// Formulas in claims.json read the same for the same function (GiNaC's own term order varies by run).
#include "experiments/claims/origin/ginac_values.hpp"
#include "theory/origin/symbols.hpp"

#include <gtest/gtest.h>

namespace affinterp::claims::ginac_values_test {
namespace {

TEST(GinacValues, ARationalFunctionOfTheOriginHasOneText) {
  const GiNaC::ex x = origin::symbols().x, y = origin::symbols().y;
  const GiNaC::ex a = (x * x + y - 2) / (2 * x + 4 * y * y + 6);
  const GiNaC::ex b = (-GiNaC::numeric(1, 2) * y - GiNaC::numeric(1, 2) * x * x + 1) / (-x - 3 - 2 * y * y);
  EXPECT_EQ(formula(a), "(1/4*x^2 + 1/4*y - 1/2)/(y^2 + 1/2*x + 3/2)");
  EXPECT_EQ(formula(a), formula(b));
  EXPECT_EQ(formula(x * x - 4 * x * y + y * y + x + y), "x^2 - 4*x*y + y^2 + x + y");
  EXPECT_EQ(formula(GiNaC::numeric(-3, 4)), "-3/4");
}

TEST(GinacValues, AnythingElseAsGinacPrintsIt) {
  const GiNaC::symbol v("v1x");
  EXPECT_EQ(formula(v), "v1x");
  EXPECT_EQ(exact_number(GiNaC::numeric(6, 4)), "3/2");
}

}  // namespace
}  // namespace affinterp::claims::ginac_values_test
