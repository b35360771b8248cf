// Every stored identity carries its step: no line `is(normal((lhs)-(rhs))==0);` of a script under
// reports/proofs/ has lhs and rhs the same text, which would have both checkers compare an expression with itself
// (the derivative, substitution or product then done by the program that wrote the script, checked by neither).
// Reads the stored files only.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace affinterp::proofs::stored_identities_test {
namespace {

/// lhs and rhs of a script line: lhs ends at the one ")-(" where the brackets opened after "is(normal((" are
/// balanced. Empty when the line is not an identity line.
std::pair<std::string, std::string> sides(const std::string& line) {
  const std::string open = "is(normal((", close = "))==0);";
  if (line.rfind(open, 0) != 0 || line.size() < open.size() + close.size()) return {};
  const std::string body = line.substr(open.size(), line.size() - open.size() - close.size());
  int depth = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (depth == 0 && body.compare(i, 3, ")-(") == 0) return {body.substr(0, i), body.substr(i + 3)};
    depth +=
        (body[i] == '(' || body[i] == '[' || body[i] == '{') - (body[i] == ')' || body[i] == ']' || body[i] == '}');
  }
  return {};
}

TEST(StoredIdentities, SplitsALineAtItsOuterMinus) {
  EXPECT_EQ(sides("is(normal((diff(x^2,x)-(1))-(2*x-1))==0);"),
            (std::pair<std::string, std::string>{"diff(x^2,x)-(1)", "2*x-1"}));
  EXPECT_EQ(sides("# a comment"), (std::pair<std::string, std::string>{}));
}

TEST(StoredIdentities, NoLineHasEqualSides) {
  const std::filesystem::path root = std::filesystem::path(AFFINTERP_SOURCE_DIR) / "reports/proofs";
  std::size_t lines = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".ginsh") continue;
    std::ifstream in(entry.path());
    std::size_t number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      const auto [lhs, rhs] = sides(line);
      if (lhs.empty()) continue;
      ++lines;
      EXPECT_NE(lhs, rhs) << std::filesystem::relative(entry.path(), root).string() << ":" << number
                          << ": both sides are the same text (the step was done before the checkers saw it)";
    }
  }
  EXPECT_GT(lines, 0u) << "no identity line found under " << root;
}

}  // namespace
}  // namespace affinterp::proofs::stored_identities_test
