// Reading QEPCAD B's, Z3's and cvc5's outputs, on outputs they printed, without running them. A transcript with
// an error, a warning or a failure anywhere answers nothing, whatever formula it printed.
#include "experiments/proofs/decider_output.hpp"

#include <gtest/gtest.h>

namespace decider_output_test {

using namespace affinterp::proofs;
using affinterp::exact::Rational;

TEST(ParseQepcad, FalseIsEmpty) {
  const std::string out =
      "Before Solution >\n\nAn equivalent quantifier-free formula:\n\nFALSE\n\n\n"
      "=====================  The End  =======================\n";
  const DeciderAnswer a = parse_qepcad(out, {"x", "y"});
  EXPECT_EQ(a.result, SetResult::empty);
  EXPECT_FALSE(a.witness);
}

TEST(ParseQepcad, TrueWithAnAlgebraicSamplePoint) {
  const std::string out = R"(Before Solution >
---------- Information about the cell (1,2) ----------
Truth value                 : T    by trial evaluation.
----------   Sample point  ---------- 
The sample point is in a PRIMITIVE representation.

alpha = the unique root of 4 x^2 + 20 x - 1 between -81/16 and -323/64
      = -5.0495097568-

Coordinate 1 = -1
             = -1.0000000000
Coordinate 2 = alpha
             = -5.0495097568-


----------------------------------------------------
---------- Information about the cell (1,8) ----------
Coordinate 1 = -1
Coordinate 2 = 3/4

Before Solution >

An equivalent quantifier-free formula:

TRUE


=====================  The End  =======================
)";
  const DeciderAnswer a = parse_qepcad(out, {"x", "y"});
  EXPECT_EQ(a.result, SetResult::non_empty);
  ASSERT_TRUE(a.witness);
  EXPECT_FALSE(a.witness->exact);
  EXPECT_EQ(a.witness->point.at("x"), Rational(-1));
  EXPECT_EQ(a.witness->point.at("y"), Rational(-50495097568LL, 10000000000LL));
}

TEST(ParseQepcad, ExactSamplePoint) {
  const std::string out =
      "Coordinate 1 = 1/8\n             = 0.125\nCoordinate 2 = 3\n             = 3.0000000000\n"
      "An equivalent quantifier-free formula:\n\nTRUE\n\n";
  const DeciderAnswer a = parse_qepcad(out, {"a", "d"});
  ASSERT_TRUE(a.witness);
  EXPECT_TRUE(a.witness->exact);
  EXPECT_EQ(a.witness->point, (affinterp::logic::Point{{"a", Rational(1, 8)}, {"d", 3}}));
}

TEST(ParseQepcad, FailuresAreUnknownWithTheReason) {
  EXPECT_EQ(parse_qepcad("Failure occurred in:    IUPRC\nPrime list exhausted\n", {"x"}).reason,
            "qepcad: Failure occurred in:    IUPRC");
  EXPECT_EQ(parse_qepcad("\nPrime list exhausted\n", {"x"}).reason, "qepcad: Prime list exhausted");
  EXPECT_EQ(parse_qepcad("\n\nToo few cells reclaimed.\n", {"x"}).reason, "qepcad: Too few cells reclaimed.");
  EXPECT_EQ(parse_qepcad("terminate called after throwing an instance of 'std::bad_alloc'\n", {"x"}).reason,
            "qepcad: out of memory (address-space cap)");
  EXPECT_EQ(parse_qepcad("", {"x"}).result, SetResult::unknown);
  const DeciderAnswer formula = parse_qepcad("An equivalent quantifier-free formula:\n\nx > 0\n\n", {"x"});
  EXPECT_EQ(formula.result, SetResult::unknown);
}

TEST(ParseQepcad, AnAnswerOverAnInvalidProjectionIsUnknown) {
  // As QEPCAD B printed it for a sentence that is not well-oriented (research run, atlas.polar.norm level D).
  const std::string out =
      "WARNING! A projection factor is everywhere zero in the cylinder \n"
      "over the cell (1609,168,6,4) of positive dimension.  The McCallum projection \n"
      "may not be valid.\n\nAn equivalent quantifier-free formula:\n\nFALSE\n\n";
  const DeciderAnswer a = parse_qepcad(out, {"x", "y", "h"});
  EXPECT_EQ(a.result, SetResult::unknown);
  EXPECT_EQ(a.reason, "qepcad: WARNING! A projection factor is everywhere zero in the cylinder");
}

TEST(ParseZ3, ModelValues) {
  const std::string out = R"(sat
(
  (define-fun a () Real
    (/ 1.0 8.0))
  (define-fun d () Real
    3.0)
  (define-fun b () Real
    (- 1.0))
  (define-fun c () Real
    (/ (- 3.0) 4.0))
)
)";
  const DeciderAnswer a = parse_smt(out, "z3");
  EXPECT_EQ(a.result, SetResult::non_empty);
  ASSERT_TRUE(a.witness);
  EXPECT_TRUE(a.witness->exact);
  EXPECT_EQ(a.witness->point,
            (affinterp::logic::Point{{"a", Rational(1, 8)}, {"b", -1}, {"c", Rational(-3, 4)}, {"d", 3}}));
}

TEST(ParseZ3, RootObjectsAreApproximated) {
  const DeciderAnswer a = parse_smt("sat\n(\n  (define-fun r () Real\n    (root-obj (+ (* x x) (- 2)) 2))\n)\n", "z3");
  ASSERT_TRUE(a.witness);
  EXPECT_FALSE(a.witness->exact);
  EXPECT_NEAR(static_cast<double>(a.witness->point.at("r")), 1.41421356237, 1e-9);
  const DeciderAnswer b = parse_smt("sat\n((define-fun r () Real (root-obj (+ (* x x) (- 2)) 1)))\n", "z3");
  EXPECT_NEAR(static_cast<double>(b.witness->point.at("r")), -1.41421356237, 1e-9);
}

TEST(ParseSmt, UnsatUnknownTimeout) {
  EXPECT_EQ(parse_smt("unsat\n", "z3").result, SetResult::empty);
  EXPECT_EQ(parse_smt("unsat\n", "cvc5").result, SetResult::empty);
  EXPECT_EQ(parse_smt("unknown\n", "z3").reason, "z3: unknown");
  EXPECT_EQ(parse_smt("timeout\n", "z3").reason, "z3: timeout");
  EXPECT_EQ(parse_smt("", "z3").result, SetResult::unknown);
}

TEST(ParseSmt, AnErrorOrAResourceMessageAnywhereAnswersNothing) {
  // Z3 and cvc5 on an input that asked for a model after "unsat" (the suite's inputs no longer do).
  const DeciderAnswer z3 = parse_smt("unsat\n(error \"line 9 column 10: model is not available\")\n", "z3");
  EXPECT_EQ(z3.result, SetResult::unknown);
  EXPECT_EQ(z3.reason, "z3: (error \"line 9 column 10: model is not available\")");
  EXPECT_EQ(parse_smt("unsat\n(error \"Cannot get model unless after a SAT or UNKNOWN response.\")\n", "cvc5").result,
            SetResult::unknown);
  EXPECT_EQ(parse_smt("cvc5 interrupted by timeout.\n", "cvc5").reason, "cvc5: cvc5 interrupted by timeout.");
  EXPECT_EQ(parse_smt("sat\n(error \"out of memory\")\n", "z3").result, SetResult::unknown);
  EXPECT_EQ(parse_smt("sat\n((define-fun x () Real (/ (- 7) 4)))\n", "cvc5").result, SetResult::non_empty);
}

// The messages QEPCAD B printed in transcripts of the second formulations (thesis.thm-2.2.1's level D and L sentences,
// thesis.thm-2.2.3's beta0.cond-not-prop.D): each with a formula after it, and each an answer of nothing.
TEST(ParseQepcad, AnErrorOrAWarningAnywhereAnswersNothing) {
  const std::string answer = "\nAn equivalent quantifier-free formula:\n\nFALSE\n\n";
  for (const std::string message : {"Error! Delineating polynomial should be added over cell(2,2)!",
                                    "WARNING! A projection factor is everywhere zero in the cylinder ",
                                    "Warning! Some 4-level projection factor is acting as a ",
                                    "over the cell (3,8,4) of positive dimension.  The McCallum projection ",
                                    "Failure occurred in:    GCSI (final check)", "Prime list exhausted"}) {
    const DeciderAnswer a = parse_qepcad("Before Solution >\n" + message + "\n" + answer, {"x"});
    EXPECT_EQ(a.result, SetResult::unknown) << message;
    EXPECT_FALSE(a.reason.empty()) << message;
  }
  // The banner names Scott McCallum: not a warning.
  EXPECT_EQ(parse_qepcad("Werner Krandick, Richard Liska, Scott McCallum,        \n" + answer, {"x"}).result,
            SetResult::empty);
}

TEST(WithoutTimings, DropsTheLinesThatVaryRunToRun) {
  EXPECT_EQ(without_timings("FALSE\n0 Garbage collections, 0 Cells and 0 Arrays reclaimed, in 0 milliseconds.\n"
                            "49386547 Cells in AVAIL, 50000000 Cells in SPACE.\nSystem time: 306 milliseconds.\n"),
            "FALSE\n49386547 Cells in AVAIL, 50000000 Cells in SPACE.\n");
}

}  // namespace decider_output_test
