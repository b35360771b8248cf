#include "theory/logic/qepcad_input.hpp"
#include "theory/logic/smtlib_input.hpp"

#include <gtest/gtest.h>

namespace writers_test {

using namespace affinterp::logic;

namespace {

QepcadInput input(std::string title, std::vector<std::string> order = {}, std::vector<std::string> commands = {}) {
  return {std::move(title), {}, std::move(order), std::move(commands)};
}

const Polynomial x = Polynomial::variable("x"), y = Polynomial::variable("y"), t = Polynomial::variable("t");

}  // namespace

TEST(QepcadInput, IntegerCoefficientsJuxtapositionAndDefaultCommands) {
  EXPECT_EQ(qepcad_polynomial(Polynomial(Rational(1, 2)) * x * y * y - Polynomial(Rational(1, 3))), "3 x y^2 - 2");
  EXPECT_EQ(qepcad_polynomial(-x + Polynomial(1)), "- x + 1");
  const Formula f = exists({"x", "y"}, greater(x, 0) && (less(y, x) || !equal(x * y, Polynomial(1))));
  EXPECT_EQ(to_qepcad(f, input("demo")),
            "[ demo ]\n(x,y)\n0\n(E x)(E y)[ [ x > 0 ] /\\ [ [ - x + y < 0 ] \\/ [ x y - 1 /= 0 ] ] ].\n"
            "go\ngo\ngo\nd-witness-list\nfinish\n");
}

TEST(QepcadInput, QuantifierAlternationOrderAndConstants) {
  const Formula f = exists({"x"}, forall({"t"}, implies(greater_equal(t, 0), greater_equal(x + t, 0))));
  EXPECT_EQ(to_qepcad(f, input("alt")), "[ alt ]\n(x,t)\n0\n(E x)(A t)[ [ t < 0 ] \\/ [ t + x >= 0 ] ].\nfinish\n");
  EXPECT_NE(to_qepcad(exists({"x", "y"}, greater(x + y, 0)), input("o", {"y", "x"})).find("(y,x)\n0\n(E y)(E x)"),
            std::string::npos);
  EXPECT_EQ(to_qepcad(truth(false), input("c", {}, {"finish"})), "[ c ]\n(zz)\n0\n(E zz)[ zz - zz /= 0 ].\nfinish\n");
}

TEST(SmtlibInput, QuantifierFreeAndQuantifiedLogics) {
  const Formula f = exists({"x", "y"}, greater(Polynomial(Rational(-1, 2)) * x * x + y, 0) && !equal(y, 3));
  EXPECT_EQ(to_smtlib(f, "demo"),
            "; demo\n(set-logic QF_NRA)\n(declare-const x Real)\n(declare-const y Real)\n"
            "(assert (and (> (+ (* (- (/ 1 2)) x x) y) 0) (not (= (+ (- 3) y) 0))))\n(check-sat)\n");
  const Formula g = exists({"x"}, forall({"t"}, greater_equal(x * t, 0)));
  EXPECT_EQ(to_smtlib(g, "g"),
            "; g\n(set-logic NRA)\n(declare-const x Real)\n(assert (forall ((t Real)) (>= (* t x) 0)))\n"
            "(check-sat)\n");
  EXPECT_THROW(to_smtlib(greater(x, 0), "free"), std::invalid_argument);
}

}  // namespace writers_test
