// The steps an identity carries (step_nodes.hpp) performed by each checker: the exact grid with its own
// arithmetic (a wrong derivative, substitution, product or determinant each found "non-zero"), GiNaC after
// perform_steps, and ginsh reading the script's text.
#include "experiments/proofs/step_nodes.hpp"
#include "experiments/proofs/exact_grid.hpp"
#include "experiments/proofs/identity.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace affinterp::proofs::step_nodes_test {
namespace {

const GiNaC::symbol x("x"), y("y"), t("t"), a("a"), s("s");

bool grid_zero(const GiNaC::ex& lhs, const GiNaC::ex& rhs) { return grid_check(lhs, rhs).zero; }

TEST(GridSteps, PerformsTheDerivative) {
  const GiNaC::ex f = GiNaC::pow(x, 3) * y + 1 / (x + 1);
  EXPECT_TRUE(grid_zero(derivative(f, x), 3 * x * x * y - 1 / GiNaC::pow(x + 1, 2)));
  EXPECT_FALSE(grid_zero(derivative(f, x), 3 * x * x * y + 1 / GiNaC::pow(x + 1, 2)));  // the quotient rule's sign
  EXPECT_FALSE(grid_zero(derivative(f, x), 3 * x * x * y));
  EXPECT_FALSE(grid_zero(derivative(f, y), 3 * x * x));  // d/dy, not d/dx
  EXPECT_TRUE(grid_zero(derivative(f, y), GiNaC::pow(x, 3)));
}

TEST(GridSteps, PerformsNestedDerivatives) {
  EXPECT_TRUE(grid_zero(derivative(GiNaC::pow(x, 4), x, 2), 12 * x * x));
  EXPECT_FALSE(grid_zero(derivative(GiNaC::pow(x, 4), x, 2), 4 * GiNaC::pow(x, 3)));
  EXPECT_TRUE(grid_zero(derivative(derivative(x * x * GiNaC::pow(y, 3), x), y), 6 * x * y * y));
  EXPECT_FALSE(grid_zero(derivative(derivative(x * x * GiNaC::pow(y, 3), x), y), 6 * x * y));
  // (x/(1+y))'' in y = 2x/(1+y)³.
  EXPECT_TRUE(grid_zero(derivative(x / (1 + y), y, 2), 2 * x / GiNaC::pow(1 + y, 3)));
  EXPECT_FALSE(grid_zero(derivative(x / (1 + y), y, 2), -2 * x / GiNaC::pow(1 + y, 3)));
}

TEST(GridSteps, LowersTheDegreeOfTheVariableDifferentiated) {
  const GridVerdict v = grid_check(derivative(GiNaC::pow(x, 5), x), 5 * GiNaC::pow(x, 4));
  ASSERT_TRUE(v.zero);
  EXPECT_EQ(v.degree_bounds.at(0), (std::pair<std::string, unsigned>{"x", 4}));
}

TEST(GridSteps, PerformsTheSubstitution) {
  const GiNaC::ex f = GiNaC::pow(t, 3) + a * t;
  EXPECT_TRUE(grid_zero(substitution(derivative(f, t), t, 2), 12 + a));
  EXPECT_FALSE(grid_zero(substitution(derivative(f, t), t, 1), 12 + a));  // a wrong point
  EXPECT_FALSE(grid_zero(derivative(substitution(f, t, 2), t), 12 + a));  // substituted first: d/dt of a constant
  EXPECT_TRUE(grid_zero(derivative(substitution(f, t, 2), t), 0));
  EXPECT_TRUE(grid_zero(substitution(s * s, s, x + 1), x * x + 2 * x + 1));  // a value that is an expression
  EXPECT_FALSE(grid_zero(substitution(s * s, s, x + 1), x * x + 1));
  EXPECT_TRUE(grid_zero(substitution(s / (1 + s), s, GiNaC::numeric(1, 3)), GiNaC::numeric(1, 4)));
  // d/dt of s·t holding s, then s = t: t (s's value does not move with the derivative).
  EXPECT_TRUE(grid_zero(substitution(derivative(s * t, t), s, t), t));
  EXPECT_FALSE(grid_zero(substitution(derivative(s * t, t), s, t), 2 * t));
  // A denominator that the substitution makes the zero polynomial: undefined, refused.
  EXPECT_THROW(grid_check(substitution(1 / (t - 1), t, 1), 0), std::invalid_argument);
}

TEST(GridSteps, PerformsProductsTransposesAndDeterminants) {
  const GiNaC::matrix A{{a, 1}, {x, y}}, B{{t, 2}, {0, x}};
  const GiNaC::ex AB = product(A, B);
  const GiNaC::ex right[] = {a * t, 2 * a + x, x * t, 2 * x + y * x};
  for (unsigned k = 0; k < 4; ++k) EXPECT_TRUE(grid_zero(entry(AB, k), right[k])) << k;
  EXPECT_FALSE(grid_zero(entry(product(B, A), 1), right[1]));  // the other order
  EXPECT_FALSE(grid_zero(entry(AB, 2), right[1]));             // another entry
  EXPECT_TRUE(grid_zero(entry(transposed(A), 1), x));
  EXPECT_FALSE(grid_zero(entry(transposed(A), 1), 1));
  EXPECT_TRUE(grid_zero(determinant_of(AB), (a * y - x) * t * x));
  EXPECT_FALSE(grid_zero(determinant_of(AB), (a * y + x) * t * x));
  const GiNaC::matrix C{{1, a, 0}, {0, 1, x}, {y, 0, 1}};
  EXPECT_TRUE(grid_zero(determinant_of(C), 1 + a * x * y));
  EXPECT_FALSE(grid_zero(determinant_of(C), 1 - a * x * y));
  EXPECT_TRUE(grid_zero(substitution(derivative(determinant_of(AB), t), t, 0), (a * y - x) * x));
}

// cos, sin and exp of a polynomial follow the chain rule: cos(g)' = −sin(g) g', to second order.
TEST(GridSteps, PerformsTheChainRuleThroughCosSinAndExp) {
  const GiNaC::symbol phi("phi"), beta("beta");
  EXPECT_TRUE(grid_zero(derivative(GiNaC::cos(t * x), t), -x * GiNaC::sin(t * x)));
  EXPECT_FALSE(grid_zero(derivative(GiNaC::cos(t * x), t), x * GiNaC::sin(t * x)));
  EXPECT_TRUE(grid_zero(derivative(GiNaC::cos(x), x, 2), -GiNaC::cos(x)));
  EXPECT_FALSE(grid_zero(derivative(GiNaC::cos(x), x, 2), GiNaC::cos(x)));
  EXPECT_TRUE(grid_zero(derivative(GiNaC::sin(x * x), x, 2), 2 * GiNaC::cos(x * x) - 4 * x * x * GiNaC::sin(x * x)));
  EXPECT_TRUE(grid_zero(derivative(GiNaC::exp(x * x), x), 2 * x * GiNaC::exp(x * x)));
  EXPECT_FALSE(grid_zero(derivative(GiNaC::exp(x * x), x), x * GiNaC::exp(x * x)));
  // The substitution names the function of the substituted argument: sin(φ + tβ) at t = 0 is sin(φ).
  EXPECT_TRUE(grid_zero(substitution(derivative(GiNaC::sin(phi + t * beta), t), t, 0), beta * GiNaC::cos(phi)));
  EXPECT_FALSE(grid_zero(substitution(derivative(GiNaC::sin(phi + t * beta), t), t, 0), beta * GiNaC::sin(phi)));
  // The derivative of x² cos x keeps degree 2 in x (cos x is a grid variable of its own, so d/dx is not ∂/∂x on
  // the grid): a wrong right side that vanishes at x = 0 and 1 is still found.
  const GiNaC::ex right = 2 * x * GiNaC::cos(x) - x * x * GiNaC::sin(x);
  EXPECT_TRUE(grid_zero(derivative(x * x * GiNaC::cos(x), x), right));
  EXPECT_FALSE(grid_zero(derivative(x * x * GiNaC::cos(x), x), right + x * (x - 1) * GiNaC::sin(x)));
}

TEST(GridSteps, RefusesAStepItCannotPerform) {
  EXPECT_THROW(grid_check(derivative(GiNaC::tan(t * x), t), 0), std::invalid_argument);       // no rule for tan
  EXPECT_THROW(grid_check(derivative(GiNaC::cos(1 / t), t), 0), std::invalid_argument);       // not a polynomial
  EXPECT_THROW(grid_check(substitution(GiNaC::cos(t * x), t, 0), 1), std::invalid_argument);  // cos 0: a number
  EXPECT_THROW(grid_check(derivative(x * x * x, x, 3), 6), std::invalid_argument);            // nested three deep
  EXPECT_NO_THROW(grid_check(derivative(GiNaC::cos(x) * t, t), GiNaC::cos(x)));
}

TEST(StepNodes, GiNaCPerformsTheStepsOnACopy) {
  const GiNaC::ex e = substitution(
      derivative(determinant_of(product(GiNaC::matrix{{a, t}, {1, x}}, GiNaC::matrix{{t, 0}, {0, 1}})), t), t, 1);
  EXPECT_TRUE(has_steps(e));
  EXPECT_TRUE((perform_steps(e) - (a * x - 2)).normal().is_zero());  // det [[at, t], [t, x]] = atx − t²
  EXPECT_TRUE(has_steps(e));                                         // e itself unchanged
}

TEST(StepNodes, TheScriptTextReadsBackToTheSameTree) {
  const GiNaC::ex e = entry(product(transposed(GiNaC::matrix{{a, t}, {1, x}}), GiNaC::matrix{{t, 0}, {0, 1}}), 2) +
                      substitution(derivative(a * t * t, t), t, GiNaC::numeric(-1, 2));
  std::ostringstream text;
  text << e;
  const GiNaC::symtab symbols{{"a", a}, {"t", t}, {"x", x}};
  EXPECT_TRUE(read_script_expression(text.str(), symbols).is_equal(e)) << text.str();
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The identity prover's script carries the steps, and ginsh performs them: 1 for the right identity, 0 for a
// wrong derivative.
TEST(StepNodes, GinshPerformsTheStepsOfTheScript) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "step-nodes-test";
  std::filesystem::remove_all(dir);
  const GiNaC::ex f = GiNaC::pow(t, 3) * x;
  const ProofSentence right = prove_identity({"right", "", substitution(derivative(f, t), t, 1), 3 * x}, {dir, "p"});
  const ProofSentence wrong = prove_identity({"wrong", "", substitution(derivative(f, t), t, 1), x}, {dir, "p"});
  EXPECT_EQ(right.result, "zero");
  EXPECT_EQ(wrong.result, "non-zero");
  EXPECT_NE(read(dir / "right.ginsh").find("subs(diff("), std::string::npos);
  if (std::system("command -v ginsh > /dev/null 2>&1") != 0) GTEST_SKIP() << "ginsh not installed";
  for (const char* name : {"right", "wrong"}) {
    const std::string out = (dir / (std::string(name) + ".txt")).string();
    ASSERT_EQ(std::system(("ginsh " + (dir / (std::string(name) + ".ginsh")).string() + " > " + out).c_str()), 0);
    EXPECT_EQ(read(out), std::string(name) == "right" ? "1\n" : "0\n");
  }
}

}  // namespace
}  // namespace affinterp::proofs::step_nodes_test
