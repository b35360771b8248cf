// thesis.exp.accuracy's evidence at the quick size (experiments/claims/sym3/thesis_exp_accuracy.cpp): the
// certified references agree with the Boost cross-check and are tight, every error counted is certified or
// excluded with its reason, ours meets its target, and the peer table covers every family and algorithm
// (AffineLib's expSym included) with a matrix for each kind of failure.
#include "experiments/claims/registry.hpp"
#include "experiments/inputs/sym3/families.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace affinterp::claims::exp_accuracy_evidence_test {
namespace {

const Outcome& outcome() {
  static const Outcome o = [] {
    RunContext run;
    run.size = Size::quick;
    return registered_claims().find("thesis.exp.accuracy")->check(run.for_claim("thesis.exp.accuracy"));
  }();
  return o;
}

TEST(ExpAccuracyEvidence, CertifiedReferencesAgreeWithTheBoostCrossCheck) {
  const nlohmann::json& references = outcome().evidence.details["references"];
  EXPECT_GT(references["boost_cross_check"]["compared"].get<int>(), 100);
  EXPECT_EQ(references["boost_cross_check"]["outside_the_ball"], 0);
  EXPECT_LT(references["max_reference_radius"].get<double>(), 1e-15);
  EXPECT_GT(references["status"]["overflows"].get<int>(), 0);  // the whole-double-range families reach it
  for (const auto& [algorithm, excluded] : references["excluded"].items())
    EXPECT_LT(excluded["largest_upper_bound_of_an_excluded_error"].get<double>(), 1e-20) << algorithm;
}

TEST(ExpAccuracyEvidence, OursMeetsItsTargetOnCertifiedErrors) {
  const nlohmann::json& target = outcome().evidence.details["affinterp_target"];
  EXPECT_TRUE(target["met"].get<bool>()) << target.dump();
  EXPECT_EQ(target["non_finite_or_overflow_mismatches"], 0);
}

TEST(ExpAccuracyEvidence, PeerTableCoversEveryFamilyAndAlgorithm) {
  const nlohmann::json& details = outcome().evidence.details;
  const auto& families = sym3::families();
  ASSERT_EQ(details["peers"].size(), families.size());
  for (const auto& family : families) {
    const nlohmann::json& row = details["peers"][family.name];
    for (const char* algorithm : {"affinterp", "eigen-direct-diag", "eigen-qr-diag", "eigen-pade", "thesis-sd-printed",
                                  "thesis-sd-corrected", "affinelib-expsym"})
      EXPECT_TRUE(row.contains(algorithm)) << family.name << " " << algorithm;
  }
  const nlohmann::json& table = details["tables"][0];
  EXPECT_EQ(table["rows"].size(), families.size());
  EXPECT_EQ(table["columns"].size(), details["peers"]["thesis"].size() + 1);
  // AffineLib's expSym forms e^λmax first: non-finite where λmax > log DBL_MAX though exp S is finite, with
  // the matrix in exact values.
  const nlohmann::json& non_finite = details["failures"]["affinelib-expsym"]["non_finite"];
  EXPECT_GT(non_finite["count"].get<int>(), 0);
  EXPECT_EQ(non_finite["example"]["judgement"], "non-finite where exp S is finite");
  EXPECT_EQ(non_finite["example"]["S_exact"].size(), 3u);
  EXPECT_TRUE(details["failures"]["affinterp"].empty()) << details["failures"]["affinterp"].dump();
}

}  // namespace
}  // namespace affinterp::claims::exp_accuracy_evidence_test
