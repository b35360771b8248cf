// What Coq's kernel has checked makes a proved claim's strength (experiments/claims/kernel_checks.hpp): a claim
// whose statement is a kernel-checked theorem is proved-kernel-checked, a proved claim naming a lemma the kernel
// has not checked names that hand step, and the committed manifest reads.
#include "experiments/claims/kernel_checks.hpp"

#include "experiments/claims/context.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace affinterp::claims::kernel_checks_test {
namespace {

Outcome proved_naming(const std::string& method) {
  Outcome out;
  out.verdict = Verdict::confirmed;
  out.strength = Strength::proved;
  out.proof = Proof{.scope = "all reals", .method = method};
  return out;
}

KernelChecks checks() {
  KernelChecks k;
  k.lemmas = {"L1", "L2"};
  k.claims = {{"a.claim", "Claims.v: a_claim"}};
  k.certificates = {{"a.claim", {2, 3}}};
  return k;
}

TEST(KernelChecks, AKernelCheckedStatementMakesTheClaimKernelChecked) {
  Outcome out = proved_naming("Lemma L1 and Lemma L7");
  apply_kernel_checks("a.claim", out, checks());
  EXPECT_EQ(out.strength, Strength::proved_kernel_checked);
  EXPECT_EQ(out.kernel_checked, "Claims.v: a_claim");
  EXPECT_TRUE(out.hand_steps.empty());
  EXPECT_EQ(out.certificates.certified, 2);
  EXPECT_EQ(out.certificates.tried, 3);
}

TEST(KernelChecks, ALemmaTheKernelHasNotCheckedIsAHandStep) {
  Outcome out = proved_naming("by L1, L2 and L7; then L1 again");
  apply_kernel_checks("other", out, checks());
  EXPECT_EQ(out.strength, Strength::proved_hand_steps);
  EXPECT_EQ(out.hand_steps, std::vector<std::string>{"L7"});
  Outcome checked = proved_naming("by L1 and L2");
  apply_kernel_checks("other", checked, checks());
  EXPECT_EQ(checked.strength, Strength::proved);
  EXPECT_EQ(lemmas_named(checked.proof.value()), (std::vector<std::string>{"L1", "L2"}));
}

TEST(KernelChecks, OtherStrengthsAreLeftAlone) {
  Outcome out = proved_naming("L7");
  out.strength = Strength::exact_counterexample;
  apply_kernel_checks("a.claim", out, checks());
  EXPECT_EQ(out.strength, Strength::exact_counterexample);
  EXPECT_FALSE(out.kernel_checked);
}

TEST(KernelChecks, TheCommittedManifestReads) {
  const KernelChecks committed = read_kernel_checks(RunSettings::committed_answers() / "coq" / "MANIFEST.json");
  EXPECT_TRUE(committed.lemmas.contains("L9"));
  EXPECT_TRUE(committed.claims.contains("thesis.thm-2.2.5"));
  EXPECT_GT(committed.certificates.at("thesis.thm-2.2.5").certified, 0);
  EXPECT_TRUE(read_kernel_checks("/nonexistent/MANIFEST.json").lemmas.empty()) << "absent: nothing checked";
  const std::filesystem::path broken = std::filesystem::temp_directory_path() / "affinterp_broken_manifest.json";
  std::ofstream(broken) << "{\"lemmas\": [";
  EXPECT_THROW(read_kernel_checks(broken), std::runtime_error);
  std::filesystem::remove(broken);
}

}  // namespace
}  // namespace affinterp::claims::kernel_checks_test
