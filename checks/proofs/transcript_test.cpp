// Proofs as data: a stored transcript keys its answer to the input it answered, and every committed
// transcript under reports/proofs/ answers the input file beside it.
#include "experiments/proofs/transcript.hpp"
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/decider.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <unistd.h>

namespace transcript_test {

using namespace affinterp::proofs;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Transcript example() { return {"z3", "4.8.12-3.1", "s.smt2", sha256_hex("(check-sat)\n"), 60, 0.25, "unsat\n"}; }

}  // namespace

TEST(Transcript, Sha256IsTheStandardOne) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Transcript, RoundTripsThroughItsText) {
  const std::optional<Transcript> t = parse_transcript(to_text(example()));
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->tool, "z3");
  EXPECT_EQ(t->version, "4.8.12-3.1");
  EXPECT_EQ(t->input, "s.smt2");
  EXPECT_EQ(t->cpu_limit_seconds, 60);
  EXPECT_EQ(t->seconds, 0.25);
  EXPECT_EQ(t->output, "unsat\n");
  EXPECT_TRUE(t->answers("z3", "(check-sat)\n"));
  EXPECT_FALSE(t->answers("z3", "(check-sat) \n")) << "another text of the sentence";
  EXPECT_FALSE(t->answers("qepcad", "(check-sat)\n")) << "another decider";
}

TEST(Transcript, KeepsCpuTimeAndPeakMemoryWhenRecorded) {
  Transcript with = example();
  with.cpu_seconds = 12.5;
  with.max_rss_kb = 786440;
  const std::optional<Transcript> t = parse_transcript(to_text(with));
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->cpu_seconds, 12.5);
  EXPECT_EQ(t->max_rss_kb, 786440);
  EXPECT_EQ(t->output, "unsat\n");
  // Transcripts written before these lines were recorded have neither.
  const std::optional<Transcript> old = parse_transcript(to_text(example()));
  ASSERT_TRUE(old.has_value());
  EXPECT_FALSE(old->cpu_seconds.has_value());
  EXPECT_FALSE(old->max_rss_kb.has_value());
}

TEST(Transcript, ATextWithoutTheHeaderIsNoTranscript) {
  EXPECT_FALSE(parse_transcript("unsat\n").has_value());
  std::string text = to_text(example());
  text.replace(text.find("sha256:") + 7, 4, "zz");  // a hash of the wrong length
  EXPECT_FALSE(parse_transcript(text).has_value());
}

TEST(DecideSentence, ReadsTheStoredAnswerAndStartsNoDecider) {
  const fs::path store = fs::temp_directory_path() / ("affinterp-store-" + std::to_string(getpid()));
  fs::remove_all(store);
  const Sentence s{
      "s",
      "x > 0 and x < 0",
      affinterp::logic::exists({"x"}, affinterp::logic::greater(affinterp::logic::Polynomial::variable("x"), 0)),
      {}};
  ProofPlan plan;
  // Nothing stored yet: unknown, and the plan records both runs.
  SentenceDecision d = decide_sentence(s, {store / "out", "proofs/test", store / "answers", &plan}, {});
  EXPECT_EQ(d.result, SetResult::unknown);
  EXPECT_NE(d.reasons().find("no stored answer"), std::string::npos) << d.reasons();
  ASSERT_EQ(plan.runs().size(), 3u) << "QEPCAD B, Z3, cvc5";
  // Store answers as `affinterp prove` would (here canned, so that no decider runs), then read them.
  for (const PlannedRun& run : plan.runs()) {
    fs::create_directories(run.store);
    const std::string output = run.decider.tool == "qepcad" ? "An equivalent quantifier-free formula:\n\nTRUE\n\n"
                                                            : "sat\n(\n  (define-fun x () Real\n    1.0)\n)\n";
    write_transcript(run.transcript_file(),
                     {std::string(run.decider.tool), "test", run.input_file().filename().string(),
                      sha256_hex(run.input_text), 60, 0.5, output});
    EXPECT_EQ(staleness(run), "decider version test → " + installed_version(run.decider));
  }
  d = decide_sentence(s, {store / "out", "proofs/test", store / "answers", nullptr}, {});
  EXPECT_EQ(d.result, SetResult::non_empty);
  EXPECT_EQ(d.runs[0].seconds, 0.5);
  EXPECT_TRUE(fs::exists(store / "out" / "s.z3.out")) << "the transcript is copied beside the written input";
  fs::remove_all(store);
}

TEST(StoredTranscripts, EveryCommittedTranscriptAnswersTheInputBesideIt) {
  int transcripts = 0;
  for (const auto& entry : fs::recursive_directory_iterator(AFFINTERP_SOURCE_DIR "/reports/proofs")) {
    const std::string name = entry.path().filename().string();
    if (!name.ends_with(".qepcad.out") && !name.ends_with(".z3.out") && !name.ends_with(".cvc5.out")) continue;
    const std::optional<Transcript> t = read_transcript(entry.path());
    ASSERT_TRUE(t.has_value()) << entry.path() << " has no transcript header";
    const fs::path input = entry.path().parent_path() / t->input;
    ASSERT_TRUE(fs::exists(input)) << entry.path() << " answers " << t->input << ", which is missing";
    EXPECT_TRUE(t->answers(t->tool, read(input))) << entry.path() << " answers another text of " << t->input;
    ++transcripts;
  }
  EXPECT_GT(transcripts, 0);
}

}  // namespace transcript_test
