// The pinned verdicts of pinned_verdicts.txt (AFFINTERP_PINNED_VERDICTS): every claim the program declares has
// exactly one line there, every line names a declared claim (a claim file the linker dropped fails here), and
// each claim still reaches its pinned verdict at the quick size; a claim marked `measured` must reach a
// measurement's verdict. And the same seed gives the same claims.json entry, apart from timings, on one thread
// and on two: each check runs twice, once per thread count, in the claim's own test process (so that ctest
// spreads the catalogue over the cores). The proofs' answers are read from the committed transcripts.
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/proof_strength.hpp"
#include "experiments/claims/registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace affinterp::claims::pinned_test {
namespace {

struct Pin {
  std::string id;
  std::optional<Verdict> verdict;  ///< none: measured, never pinned
  int line = 0;
};

void PrintTo(const Pin& pin, std::ostream* os) {
  *os << pin.id << " = " << (pin.verdict ? to_string(*pin.verdict) : "measured");
}

struct PinFile {
  std::vector<Pin> pins;
  std::vector<std::string> errors;  ///< "line N: what is wrong"
};

/// Reads "ID verdict  # why" lines; blank lines and comments are skipped, malformed lines reported.
PinFile read_pin_file() {
  PinFile file;
  std::ifstream in(AFFINTERP_PINNED_VERDICTS);
  if (!in) file.errors.push_back("cannot read " AFFINTERP_PINNED_VERDICTS);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream fields(text.substr(0, text.find('#')));
    std::string id, verdict, extra;
    if (!(fields >> id)) continue;
    if (!(fields >> verdict) || fields >> extra) {
      file.errors.push_back("line " + std::to_string(line) + ": want 'ID verdict', got '" + text + "'");
      continue;
    }
    if (verdict == "measured") {
      file.pins.push_back({id, std::nullopt, line});
    } else if (const auto parsed = parse_verdict(verdict)) {
      file.pins.push_back({id, parsed, line});
    } else {
      file.errors.push_back("line " + std::to_string(line) + ": unknown verdict '" + verdict + "'");
    }
  }
  return file;
}

const PinFile& pin_file() {
  static const PinFile file = read_pin_file();
  return file;
}

TEST(PinnedVerdicts, NameEveryDeclaredClaimOnce) {
  for (const std::string& error : pin_file().errors) ADD_FAILURE() << AFFINTERP_PINNED_VERDICTS ": " << error;
  std::map<std::string, int, std::less<>> lines;
  for (const Pin& pin : pin_file().pins) {
    EXPECT_TRUE(lines.emplace(pin.id, pin.line).second) << pin.id << " is pinned twice (line " << pin.line << ")";
    EXPECT_NE(registered_claims().find(pin.id), nullptr)
        << "line " << pin.line << " pins " << pin.id << ", which no claim file declares (or the linker dropped it)";
  }
  for (const Claim& claim : registered_claims().claims())
    EXPECT_TRUE(lines.contains(claim.id))
        << claim.id << " is declared but neither pinned nor marked measured in " << AFFINTERP_PINNED_VERDICTS;
}

TEST(PinnedVerdicts, EveryClaimSaysHowStrongItsVerdictIs) {
  for (const Claim& claim : registered_claims().claims())
    EXPECT_NE(claim.strength, Strength::unstated) << claim.id << " declares no strength (grid, sample, ...)";
}

/// The entry as claims.json writes it, less its timings. (Text, not JSON values: a NaN in the evidence is
/// written as null, and compares unequal to itself as a value.)
std::string without_timings(const Claim& claim, const Outcome& outcome) {
  nlohmann::json entry = to_json({&claim, outcome, 0, {}});
  entry.erase("seconds");
  entry["evidence"].erase("measurements");
  if (entry["proof"].is_object())
    for (auto& sentence : entry["proof"]["sentences"]) {
      sentence.erase("seconds");
      for (auto& run : sentence["runs"]) run.erase("seconds");
    }
  return entry.dump(1);
}

Outcome check_on(const Claim& claim, unsigned threads) {
  RunContext run;
  run.size = Size::quick;
  run.threads = threads;
  return claim.check(run.for_claim(claim.id));
}

class PinnedVerdict : public testing::TestWithParam<Pin> {};

TEST_P(PinnedVerdict, StillHoldsAndIsTheSameOnOneAndTwoThreads) {
  const Pin& pin = GetParam();
  const Claim* claim = registered_claims().find(pin.id);
  ASSERT_NE(claim, nullptr) << pin.id << " is pinned but not declared";
  ASSERT_TRUE(claim->check) << pin.id << " is pinned but has no check";
  const Outcome outcome = check_on(*claim, 2);
  EXPECT_EQ(without_timings(*claim, check_on(*claim, 1)), without_timings(*claim, outcome))
      << pin.id << " is not deterministic";
  if (is_proved(outcome.strength)) {
    ASSERT_TRUE(outcome.proof.has_value()) << pin.id << " says proved but carries no proof";
    EXPECT_EQ(proof_strength(*outcome.proof), outcome.strength)
        << pin.id << ": the strength is the proof's, computed from what its checkers answered";
  }
  if (pin.verdict) {
    EXPECT_EQ(to_string(outcome.verdict), to_string(*pin.verdict))
        << "the verdict on " << pin.id << " changed from its pinned value: " << outcome.summary;
  } else {
    EXPECT_TRUE(outcome.verdict == Verdict::reproduced || outcome.verdict == Verdict::not_reproduced ||
                outcome.verdict == Verdict::inconclusive)
        << pin.id << " is marked measured but decides '" << to_string(outcome.verdict)
        << "' without benchmark data: pin that verdict instead";
  }
}

INSTANTIATE_TEST_SUITE_P(Claims, PinnedVerdict, testing::ValuesIn(pin_file().pins),
                         [](const testing::TestParamInfo<Pin>& info) { return file_stem(info.param.id); });

}  // namespace
}  // namespace affinterp::claims::pinned_test
