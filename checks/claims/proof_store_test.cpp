// Proofs as data: every decider run the claims' proofs need has a stored transcript answering the
// sentence's current text, so that the checks, which only read answers, decide what the committed report says.
// A sentence edited without `affinterp prove` fails here, naming it; no decider runs.
#include "experiments/claims/runner.hpp"
#include "experiments/proofs/proof_plan.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace affinterp::claims::proof_store_test {
namespace {

TEST(ProofStore, EveryPlannedDeciderRunHasAStoredAnswerForTheSentenceAsBuiltToday) {
  proofs::ProofPlan plan;
  RunContext context;
  context.size = Size::quick;
  context.threads = 2;
  context.plan = &plan;
  std::ostringstream progress;
  for (const ClaimResult& r : run_claims(registered_claims(), context, {}, progress))
    EXPECT_EQ(r.error, "") << r.claim->id;
  const std::vector<proofs::PlannedRun> runs = plan.runs();
  EXPECT_GT(runs.size(), 300u) << "the proofs of the local claims, the atlas, E^R, §2.3 and Viète";
  for (const proofs::PlannedRun& run : runs) {
    const std::optional<proofs::Transcript> t = proofs::read_transcript(run.transcript_file());
    ASSERT_TRUE(t.has_value()) << run.transcript_file() << " is missing: run `affinterp prove` and commit it";
    EXPECT_TRUE(t->answers(run.decider.tool, run.input_text))
        << run.transcript_file() << " answers another text of the sentence: run `affinterp prove` and commit it";
  }
}

}  // namespace
}  // namespace affinterp::claims::proof_store_test
