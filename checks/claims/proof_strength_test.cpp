// The strength of a proved verdict is computed from its formulations' runs: one complete formulation
// answered by two deciders and citing nothing makes the claim `proved`; otherwise the lemma chain's label holds.
#include "experiments/claims/proof_strength.hpp"

#include <gtest/gtest.h>

namespace affinterp::claims::proof_strength_test {
namespace {

using proofs::Proof;
using proofs::ProofSentence;

/// One sentence answered "empty" by each of `tools` and "unknown" by cvc5.
ProofSentence empty_by(const std::vector<std::string>& tools) {
  ProofSentence s{"s", "a sentence", "empty", {}, false};
  for (const std::string& tool : tools) s.runs.push_back({tool, "s." + tool, "empty", 0.1});
  s.runs.push_back({"cvc5", "s.smt2", "unknown", 20.0});
  return s;
}

Proof formulation(const std::vector<std::string>& tools, std::string cites = "") {
  Proof p{"scope", "method", tools, {empty_by(tools)}};
  p.cites = std::move(cites);
  return p;
}

TEST(ProofStrength, AFormulationAnsweredByTwoDecidersWithoutCitationMakesTheClaimProved) {
  Proof chain = formulation({"qepcad", "z3"}, "Dines' theorem");
  EXPECT_EQ(proof_strength(chain), Strength::proved_citing);
  chain.formulations.push_back(formulation({"qepcad"}));
  EXPECT_EQ(proof_strength(chain), Strength::proved_citing) << "one decider does not lift the citation";
  chain.formulations.push_back(formulation({"qepcad", "z3"}));
  EXPECT_EQ(proof_strength(chain), Strength::proved);
}

TEST(ProofStrength, AnUndecidedChainTakesTheFormulationsLabel) {
  Proof chain = formulation({"qepcad", "z3"});
  chain.sentences.front().result = "unknown";
  for (auto& run : chain.sentences.front().runs) run.result = "unknown";
  EXPECT_FALSE(proof_strength(chain).has_value());
  chain.formulations.push_back(formulation({"z3"}));
  EXPECT_EQ(proof_strength(chain), Strength::proved_one_decider);
}

TEST(ProofStrength, AFormulationOfStructuralSentencesProvesNothing) {
  Proof chain = formulation({"qepcad", "z3"}, "the exponential");
  Proof structural = formulation({"qepcad", "z3"});
  structural.sentences.front().structural = true;
  chain.formulations.push_back(structural);
  EXPECT_EQ(proof_strength(chain), Strength::proved_citing);
}

}  // namespace
}  // namespace affinterp::claims::proof_strength_test
