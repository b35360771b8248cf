// The claims engine: registry, runner, claims.json, staged outputs, parallel sweeps.
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/registry.hpp"
#include "experiments/claims/runner.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/support/parallel.hpp"
#include "experiments/support/staged_output.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <set>
#include <sstream>

namespace engine_test {

using namespace affinterp;
using namespace affinterp::claims;
using affinterp::exact::Mat2Q;
namespace fs = std::filesystem;

namespace {

/// A claim with the given ID and check, for registries built by hand.
Claim claim(std::string_view id, Check check = {}, Chapter chapter = Chapter::local) {
  return {id, chapter, "Kaji §3", "a statement", Strength::sample, std::move(check)};
}

}  // namespace

TEST(Registry, RefusesMalformedRepeatedAndUnstatedClaims) {
  ClaimRegistry registry;
  EXPECT_THROW(registry.add(claim("polar.det")), std::logic_error);
  EXPECT_THROW(registry.add(claim("kaji.polar det")), std::logic_error);
  registry.add(claim("kaji.polar.det"));
  EXPECT_THROW(registry.add(claim("kaji.polar.det")), std::logic_error);
  EXPECT_THROW(registry.add({"kaji.no-statement", Chapter::local, "Kaji §3", "", Strength::sample, {}}),
               std::logic_error);
}

TEST(Registry, KeepsRunOrderWhateverTheOrderOfDeclaration) {
  ClaimRegistry registry;
  for (const char* id : {"thesis.thm-2.2.10", "kaji.z", "thesis.thm-2.2.9", "kaji.a"}) registry.add(claim(id));
  registry.add(claim("kaji.b", {}, Chapter::global));
  registry.add(claim("kaji.a.sym3", {}, Chapter::sym3));
  std::vector<std::string_view> order;
  for (const Claim& c : registry.claims()) order.push_back(c.id);
  EXPECT_EQ(order, (std::vector<std::string_view>{"kaji.a", "kaji.z", "thesis.thm-2.2.9", "thesis.thm-2.2.10", "kaji.b",
                                                  "kaji.a.sym3"}));
}

TEST(Registry, EachClaimLivesInTheFileItsIdNames) {
  // experiments/claims/<chapter>/<file_stem(id)>.cpp, or a folder of that name for a large claim; and every
  // such file in a chapter folder declares a claim (a file missing from CMakeLists.txt declares nothing).
  const fs::path claims_dir = fs::path(AFFINTERP_SOURCE_DIR) / "experiments" / "claims";
  std::set<fs::path> expected;
  for (const Claim& c : registered_claims().claims()) {
    const fs::path stem = claims_dir / to_string(c.chapter) / file_stem(c.id);
    EXPECT_TRUE(fs::exists(fs::path(stem).concat(".cpp")) || fs::is_directory(stem))
        << c.id << " is not declared in " << stem.string() << ".cpp";
    expected.insert(stem);
  }
  for (const Chapter chapter : {Chapter::local, Chapter::global, Chapter::origin, Chapter::sym3, Chapter::atlas,
                                Chapter::atlas3, Chapter::global3})
    for (const auto& entry : fs::directory_iterator(claims_dir / to_string(chapter))) {
      const std::string name = entry.path().stem().string();
      if (!name.starts_with("kaji_") && !name.starts_with("thesis_") && !name.starts_with("atlas") &&
          !name.starts_with("sequel_"))
        continue;
      EXPECT_TRUE(expected.contains(entry.path().parent_path() / name))
          << entry.path().string() << " is named like a claim file but declares no claim of this program";
    }
  EXPECT_FALSE(registered_claims().claims().empty());
}

TEST(Runner, UnimplementedClaimIsPendingAndFailuresAreReported) {
  ClaimRegistry registry;
  registry.add(claim("kaji.linear.collapse", [](const ClaimContext&) -> Outcome { throw std::runtime_error("boom"); }));
  registry.add(claim("kaji.polar.det"));
  std::ostringstream progress;
  const auto results = run_claims(registry, RunContext{}, {"kaji.polar.det", "kaji.linear.collapse"}, progress);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].claim->id, "kaji.linear.collapse");
  EXPECT_EQ(results[0].error, "boom");
  EXPECT_EQ(results[1].outcome.verdict, Verdict::pending);
  EXPECT_NE(progress.str().find("2/2] kaji.polar.det"), std::string::npos);
  EXPECT_THROW(run_claims(registry, RunContext{}, {"nope"}, progress), std::invalid_argument);
}

TEST(Runner, HandsEachCheckItsOwnSeed) {
  ClaimRegistry registry;
  std::uint64_t seen = 0;
  std::string_view seen_id;
  registry.add(claim("kaji.polar.det", [&](const ClaimContext& ctx) {
    seen = ctx.seed, seen_id = ctx.claim_id;
    return Outcome{};
  }));
  RunContext run;
  run.seed = 7;
  std::ostringstream progress;
  run_claims(registry, run, {}, progress);
  EXPECT_EQ(seen, run.seed_for("kaji.polar.det"));
  EXPECT_EQ(seen_id, "kaji.polar.det");
}

TEST(ClaimsJson, HasTheRequiredFieldsAndKeepsEarlierEntries) {
  ClaimRegistry registry;
  registry.add(claim("kaji.linear.collapse", [](const ClaimContext&) {
    Outcome o;
    o.verdict = Verdict::refuted;
    o.summary = "s";
    o.counterexample = {{"A", exact_matrix(Mat2Q{{-1, 0}, {0, -1}})}};
    o.figures = {"figures/f.png"};
    return o;
  }));
  registry.add(claim("kaji.polar.det"));
  std::ostringstream progress;
  const auto results = run_claims(registry, RunContext{}, {"kaji.linear.collapse"}, progress);
  const nlohmann::json previous = {{"claims", {{{"id", "kaji.polar.det"}, {"verdict", "confirmed"}}}}};
  const auto doc = claims_document(registry, results, RunContext{}, {{"cpu", "x"}}, previous, {});
  ASSERT_EQ(doc["claims"].size(), 2u);
  const auto& c = doc["claims"][0];
  EXPECT_EQ(c["id"], "kaji.linear.collapse");
  EXPECT_EQ(c["group"], report_section(Chapter::local));
  EXPECT_EQ(c["verdict"], "refuted");
  for (const char* key : {"summary", "evidence", "counterexample", "correction", "figures"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(c["counterexample"]["A"][0][0], "-1");
  EXPECT_EQ(doc["claims"][1]["verdict"], "confirmed");
}

TEST(RunContext, PerClaimSeedsAreStableAndDistinct) {
  RunContext a, b;
  b.seed = 7;
  // Every report since the first derives its samples from these seeds: a change of formula changes them all.
  EXPECT_EQ(a.seed_for("kaji.polar.det"), 4116998486360748952ull);
  EXPECT_NE(a.seed_for("kaji.polar.det"), a.seed_for("kaji.exp.det-positive"));
  EXPECT_NE(a.seed_for("kaji.polar.det"), b.seed_for("kaji.polar.det"));
  EXPECT_EQ(a.for_claim("kaji.polar.det").seed, a.seed_for("kaji.polar.det"));
}

TEST(Parallel, ChunkResultsComeBackInOrderForAnyThreadCount) {
  auto sum_chunks = [](unsigned threads) {
    return parallel_chunks(1000, threads, 37, [](std::size_t begin, std::size_t end) {
      std::size_t s = 0;
      for (std::size_t i = begin; i < end; ++i) s += i * i;
      return s;
    });
  };
  EXPECT_EQ(sum_chunks(1), sum_chunks(4));
  const auto chunks = sum_chunks(3);
  EXPECT_EQ(std::accumulate(chunks.begin(), chunks.end(), std::size_t{0}), 332833500u);
  EXPECT_THROW(parallel_chunks(10, 2, 1,
                               [](std::size_t b, std::size_t) -> int {
                                 if (b == 5) throw std::runtime_error("x");
                                 return 0;
                               }),
               std::runtime_error);
}

TEST(StagedOutput, CommitsOnSuccessAndLeavesEarlierOutputsOtherwise) {
  const fs::path target = fs::temp_directory_path() / "affinterp_staged_test";
  fs::remove_all(target);
  fs::create_directories(target);
  std::ofstream(target / "keep.txt") << "old";
  {
    StagedOutput failed(target);
    std::ofstream(failed.staging() / "keep.txt") << "new";
  }  // not committed: discarded
  std::ifstream in(target / "keep.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  {
    StagedOutput ok(target);
    fs::create_directories(ok.staging() / "figures");
    std::ofstream(ok.staging() / "figures" / "f.png") << "png";
    ok.commit();
  }
  EXPECT_TRUE(fs::exists(target / "figures" / "f.png"));
  EXPECT_TRUE(fs::exists(target / "keep.txt"));
  fs::remove_all(target);
}

}  // namespace engine_test
