// The proofs attached to the algebraic claims of Kaji's E^R, thesis §2.3 and chapter 3 and to the local,
// spectral-decomposition and E^F frame claims: every confirmed one is proved for all reals, every refuted or
// corrected one keeps its exact counterexample with the proof attached.
#include "experiments/claims/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace affinterp::claims::identity_proofs_test {
namespace {

Outcome run(const std::string& id) {
  const Claim* claim = registered_claims().find(id);
  EXPECT_NE(claim, nullptr) << id;
  RunContext context;
  context.size = Size::quick;
  Outcome outcome = claim->check(context.for_claim(claim->id));
  if (outcome.strength == Strength::unstated) outcome.strength = claim->strength;  // as the runner does
  return outcome;
}

class ConfirmedByIdentities : public testing::TestWithParam<const char*> {};

TEST_P(ConfirmedByIdentities, IsProvedByGinacAndTheExactGrid) {
  const Outcome outcome = run(GetParam());
  EXPECT_EQ(outcome.verdict, Verdict::confirmed);
  EXPECT_EQ(outcome.strength, Strength::proved);
  ASSERT_TRUE(outcome.proof.has_value());
  EXPECT_EQ(outcome.proof->checked_by, (std::vector<std::string>{"ginac", "exact-grid"}));
}
INSTANTIATE_TEST_SUITE_P(Claims, ConfirmedByIdentities,
                         testing::Values("kaji.er.closed-form", "kaji.er.similarity-invariant", "thesis.eq-3.charpoly",
                                         "kaji.appendix.polar-from-svd", "kaji.exp.endpoints", "kaji.linear.collapse",
                                         "thesis.sd.case1", "thesis.sd.case2", "kaji.eq1.affine-map",
                                         "kaji.ef.translation-invariant"));

class CorrectedByIdentities : public testing::TestWithParam<const char*> {};

TEST_P(CorrectedByIdentities, KeepsItsCounterexampleAndIsProvedByGinacAndTheExactGrid) {
  const Outcome outcome = run(GetParam());
  EXPECT_EQ(outcome.verdict, Verdict::corrected);
  EXPECT_EQ(outcome.strength, Strength::proved);
  EXPECT_FALSE(outcome.counterexample.is_null());
  ASSERT_TRUE(outcome.proof.has_value());
  EXPECT_EQ(outcome.proof->checked_by, (std::vector<std::string>{"ginac", "exact-grid"}));
}
INSTANTIATE_TEST_SUITE_P(Claims, CorrectedByIdentities, testing::Values("kaji.acol.constraint"));

class ConfirmedByIdentitiesAndSentences : public testing::TestWithParam<const char*> {};

TEST_P(ConfirmedByIdentitiesAndSentences, IsProvedByTheStoredAnswersOfQepcadAndZ3) {
  const Outcome outcome = run(GetParam());
  EXPECT_EQ(outcome.verdict, Verdict::confirmed);
  EXPECT_EQ(outcome.strength, Strength::proved);
  ASSERT_TRUE(outcome.proof.has_value());
  EXPECT_EQ(outcome.proof->checked_by, (std::vector<std::string>{"ginac", "exact-grid", "qepcad", "z3"}));
}
INSTANTIATE_TEST_SUITE_P(Claims, ConfirmedByIdentitiesAndSentences,
                         testing::Values("thesis.sec-2.3.minimiser", "thesis.sec-2.3.min-energy", "thesis.viete"));

class FailsAsPrinted : public testing::TestWithParam<const char*> {};

TEST_P(FailsAsPrinted, KeepsItsExactCounterexampleWithTheProofAttached) {
  const Outcome outcome = run(GetParam());
  EXPECT_TRUE(outcome.verdict == Verdict::refuted || outcome.verdict == Verdict::corrected);
  EXPECT_EQ(outcome.strength, Strength::exact_counterexample);
  EXPECT_FALSE(outcome.counterexample.is_null());
  ASSERT_TRUE(outcome.proof.has_value());
  for (const ProofSentence& s : outcome.proof->sentences) EXPECT_NE(s.result, "unknown") << s.name;
}
INSTANTIATE_TEST_SUITE_P(Claims, FailsAsPrinted,
                         testing::Values("kaji.er.positive-definite", "thesis.sec-2.3.matrices", "thesis.sec-2.3.conic",
                                         "thesis.sd.case3"));

}  // namespace
}  // namespace affinterp::claims::identity_proofs_test
