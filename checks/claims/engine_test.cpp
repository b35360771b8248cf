// The claims engine: catalogue, registry, runner, claims.json, staged outputs, parallel sweeps.
#include "experiments/claims/catalogue.hpp"
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/registry.hpp"
#include "experiments/claims/runner.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/support/parallel.hpp"
#include "experiments/support/staged_output.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>

using namespace affinterp;
using namespace affinterp::claims;
using affinterp::exact::Mat2Q;
namespace fs = std::filesystem;

TEST(Catalogue, IdsAreUniqueAndWellFormed) {
  std::set<std::string_view> seen;
  const std::regex form(R"((kaji|thesis)\.[A-Za-z0-9.-]+)");
  for (const auto& c : catalogue()) {
    EXPECT_TRUE(seen.insert(c.id).second) << c.id;
    EXPECT_TRUE(std::regex_match(std::string(c.id), form)) << c.id;
    EXPECT_FALSE(c.statement.empty()) << c.id;
  }
  EXPECT_EQ(seen.size(), 41u);
}

TEST(Registry, RefusesUnknownAndDuplicateClaims) {
  CheckRegistry registry;
  const Check check = [](const RunContext&) { return Outcome{}; };
  EXPECT_THROW(registry.add("kaji.no-such-claim", check), std::logic_error);
  registry.add("kaji.polar.det", check);
  EXPECT_THROW(registry.add("kaji.polar.det", check), std::logic_error);
}

TEST(Registry, EveryRegisteredCheckIsCatalogued) {
  // build_registry() throws on an uncatalogued ID, so building it is the test.
  EXPECT_NO_THROW(build_registry());
}

TEST(Runner, UnimplementedClaimIsPendingAndFailuresAreReported) {
  CheckRegistry registry;
  registry.add("kaji.linear.collapse", [](const RunContext&) -> Outcome { throw std::runtime_error("boom"); });
  std::ostringstream progress;
  const auto results = run_claims(registry, RunContext{}, {"kaji.linear.collapse", "kaji.polar.det"}, progress);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].info->id, "kaji.linear.collapse");
  EXPECT_EQ(results[0].error, "boom");
  EXPECT_EQ(results[1].outcome.verdict, Verdict::pending);
  EXPECT_NE(progress.str().find("2/2] kaji.polar.det"), std::string::npos);
  EXPECT_THROW(run_claims(registry, RunContext{}, {"nope"}, progress), std::invalid_argument);
}

TEST(ClaimsJson, HasTheRequiredFieldsAndKeepsEarlierEntries) {
  CheckRegistry registry;
  registry.add("kaji.linear.collapse", [](const RunContext&) {
    Outcome o;
    o.verdict = Verdict::refuted;
    o.summary = "s";
    o.counterexample = {{"A", exact_matrix(Mat2Q{{-1, 0}, {0, -1}})}};
    o.figures = {"figures/f.png"};
    return o;
  });
  std::ostringstream progress;
  const auto results = run_claims(registry, RunContext{}, {"kaji.linear.collapse"}, progress);
  const nlohmann::json previous = {{"claims", {{{"id", "kaji.polar.det"}, {"verdict", "confirmed"}}}}};
  const auto doc = claims_document(results, RunContext{}, {{"cpu", "x"}}, previous);
  ASSERT_EQ(doc["claims"].size(), 2u);
  const auto& c = doc["claims"][0];
  EXPECT_EQ(c["id"], "kaji.linear.collapse");
  EXPECT_EQ(c["verdict"], "refuted");
  for (const char* key : {"summary", "evidence", "counterexample", "correction", "figures"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(c["counterexample"]["A"][0][0], "-1");
  EXPECT_EQ(doc["claims"][1]["verdict"], "confirmed");
}

TEST(RunContext, PerClaimSeedsAreStableAndDistinct) {
  RunContext a, b;
  b.seed = 7;
  EXPECT_EQ(a.seed_for("kaji.polar.det"), RunContext{}.seed_for("kaji.polar.det"));
  EXPECT_NE(a.seed_for("kaji.polar.det"), a.seed_for("kaji.exp.det-positive"));
  EXPECT_NE(a.seed_for("kaji.polar.det"), b.seed_for("kaji.polar.det"));
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
  EXPECT_THROW(parallel_chunks(10, 2, 1, [](std::size_t b, std::size_t) -> int {
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
