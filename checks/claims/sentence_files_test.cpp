// The committed sentence files reports/proofs/<claim id>/<name>.qepcad and .smt2 are what the claims build today,
// byte for byte: every claim that declares its sentences (claim_sentences.hpp) builds them at the report's full size,
// and each is written as proofs::decide_sentence writes it (theory/logic's to_qepcad and to_smtlib, titled
// "<claim id> <name>"), with no decider run. A decided answer belongs to the text of its sentence, so a change of a
// builder that alters a sentence shows here, naming the file.
#include "experiments/claims/claim_sentences.hpp"
#include "experiments/claims/registry.hpp"
#include "theory/logic/qepcad_input.hpp"
#include "theory/logic/smtlib_input.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace affinterp::claims {
namespace {

namespace fs = std::filesystem;

const fs::path committed_proofs = fs::path(AFFINTERP_SOURCE_DIR) / "reports" / "proofs";

/// The file's text, or nullopt when there is none.
std::optional<std::string> read_text(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Compares one written text with the committed file.
void expect_committed(const fs::path& file, const std::string& text) {
  const std::optional<std::string> committed = read_text(file);
  if (!committed)
    ADD_FAILURE() << file << " is not committed";
  else
    EXPECT_EQ(*committed, text) << file << " differs from what the builders write";
}

TEST(SentenceFiles, EveryLocalAndAtlasProofDeclaresItsSentences) {
  std::set<Chapter> chapters;
  for (const auto& [id, build] : declared_sentences()) {
    const Claim* claim = registered_claims().find(id);
    ASSERT_NE(claim, nullptr) << "sentences declared for " << id << ", which is no claim";
    chapters.insert(claim->chapter);
  }
  EXPECT_TRUE(chapters.contains(Chapter::local));
  EXPECT_TRUE(chapters.contains(Chapter::atlas));
}

TEST(SentenceFiles, TheBuildersWriteTheCommittedFiles) {
  RunContext run;
  run.size = Size::full;  // the size the committed report was run at
  for (const auto& [id, build] : declared_sentences()) {
    const ClaimContext ctx = run.for_claim(id);
    const fs::path dir = committed_proofs / id;
    const std::string title_prefix = fs::path(ctx.proof_files().reference).filename().string() + " ";
    std::set<std::string> built;
    for (const proofs::Sentence& s : build(ctx)) {
      SCOPED_TRACE(id + " " + s.name);
      const std::string title = title_prefix + s.name;
      expect_committed(
          dir / (s.name + ".qepcad"),
          logic::to_qepcad(s.formula, {.title = title, .free = {}, .order = s.qepcad_order, .commands = {}}));
      expect_committed(dir / (s.name + ".smt2"), logic::to_smtlib(s.formula, title));
      built.insert(s.name);
    }
    // And no committed sentence is left that the claim no longer builds.
    if (!fs::is_directory(dir)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".qepcad") continue;
      EXPECT_TRUE(built.contains(e.path().stem().string())) << e.path() << " is built by no sentence of " << id;
    }
  }
}

}  // namespace
}  // namespace affinterp::claims
