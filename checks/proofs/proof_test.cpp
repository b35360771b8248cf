// What a proof records: which deciders decided every sentence, when it proves an equivalence, and what was tried.
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/formulation.hpp"

#include <gtest/gtest.h>

namespace proof_test {

using namespace affinterp::proofs;

namespace {

ProofSentence sentence(const std::string& name, const std::string& result, const std::string& qepcad,
                       const std::string& z3) {
  return {name, "", result, {{"qepcad", name + ".qepcad", qepcad, 1.0}, {"z3", name + ".smt2", z3, 0.1}}};
}

}  // namespace

TEST(Proof, TwoDecidersOnEverySentenceProveAnEquivalence) {
  const Proof p = make_proof(
      "det A > 0", "level E",
      {sentence("cond-not-prop", "empty", "empty", "empty"), sentence("prop-not-cond", "empty", "empty", "empty")});
  EXPECT_EQ(p.checked_by, (std::vector<std::string>{"qepcad", "z3"}));
  EXPECT_TRUE(p.decided_by_two());
  EXPECT_TRUE(p.all_empty());
}

TEST(Proof, ADeciderThatFailedOnOneSentenceIsNotNamed) {
  const Proof p = make_proof("", "",
                             {sentence("cond-not-prop", "empty", "unknown", "empty"),
                              sentence("prop-not-cond", "non-empty", "non-empty", "non-empty")});
  EXPECT_EQ(p.checked_by, (std::vector<std::string>{"z3"}));
  EXPECT_FALSE(p.decided_by_two());
  EXPECT_FALSE(p.all_empty());
}

TEST(Formulation, UnansweredRunsAreAttemptsWithTheirFormulation) {
  Proof p = make_proof("", "", {sentence("cond-not-prop.L", "empty", "unknown", "empty")});
  p.sentences.front().runs.front().reason = "qepcad: no answer within the time limit";
  p.sentences.front().runs.front().cpu_seconds = 600.2;
  const std::vector<Attempt> attempts = unanswered_runs(p, "level L");
  ASSERT_EQ(attempts.size(), 1u);
  EXPECT_EQ(attempts[0].formulation, "level L");
  EXPECT_EQ(attempts[0].sentence, "cond-not-prop.L");
  EXPECT_EQ(attempts[0].tool, "qepcad");
  EXPECT_EQ(attempts[0].cpu_seconds, 600.2);
  EXPECT_EQ(attempts[0].outcome, "qepcad: no answer within the time limit");
}

TEST(Formulation, AFormulationNoDeciderCanBeGivenIsRecordedWithItsReason) {
  const std::vector<Attempt> attempts =
      decide_attempt({.formulation = "as written", .sentences = {}, .not_expressible = "transcendental in t"}, {});
  ASSERT_EQ(attempts.size(), 1u);
  EXPECT_TRUE(attempts[0].tool.empty());
  EXPECT_EQ(attempts[0].outcome, "transcendental in t");
}

}  // namespace proof_test
