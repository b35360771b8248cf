// What a proof records: which deciders decided every sentence, and when it proves an equivalence.
#include "experiments/proofs/decide_sentence.hpp"

#include <gtest/gtest.h>

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
