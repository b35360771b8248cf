// A deterministic mutation fuzzer for the mesh reader (runs wherever the suite builds; the libFuzzer
// target, when clang is present, explores further): byte, token and line mutations of valid OBJ/OFF
// files, including NUL bytes, huge and negative counts and indices, non-numbers and truncation. Every
// input must end in a mesh or a one-line error (fuzz::mesh_reader_one_input aborts otherwise).
#include "checks/inputs/fuzz/mesh_reader_fuzz.hpp"
#include "experiments/support/random.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <string>
#include <vector>

namespace mesh_reader_fuzz_test {

namespace {

using affinterp::Rng;

const std::vector<std::string>& seeds() {
  static const std::vector<std::string> texts = {
      "# two triangles\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1//1 3//1 -1\n",
      "OFF\n# two triangles\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3 255 0 0\n",
      "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      "v 0 0\nv 2 0\nv 0 2\nv 2 2\nf 1 3 2\nf 2 3 4\n",
  };
  return texts;
}

/// Tokens a mutation may splice in: extremes of every field the reader parses.
constexpr std::array<const char*, 22> tokens = {
    "0",   "-1",  "-4",  "3",     "4",      "2147483647", "2147483648", "99999999999999999999",
    "-0",  "nan", "inf", "1e400", "1e-400", "+1",         "f",          "v",
    "OFF", "/",   "//",  "#",     "\t",     " 3 0 1 2 "};

std::string mutate(std::string text, Rng& rng) {
  const int steps = static_cast<int>(rng.integer(1, 4));
  for (int s = 0; s < steps; ++s) {
    const std::size_t at =
        text.empty() ? 0 : static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(text.size()) - 1));
    switch (rng.integer(0, 6)) {
      case 0:  // overwrite a byte with any byte, NUL included
        if (!text.empty()) text[at] = static_cast<char>(rng.integer(0, 255));
        break;
      case 1:  // insert a token
        text.insert(at, tokens[static_cast<std::size_t>(rng.integer(0, tokens.size() - 1))]);
        break;
      case 2:  // delete a range
        text.erase(at, static_cast<std::size_t>(rng.integer(1, 8)));
        break;
      case 3:  // truncate
        text.resize(at);
        break;
      case 4: {  // duplicate the line at `at`
        const std::size_t begin = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const std::size_t end = text.find('\n', at);
        text.insert(begin, text.substr(begin, end == std::string::npos ? std::string::npos : end - begin + 1));
        break;
      }
      case 5:  // replace a digit run by an extreme number
        if (!text.empty() && std::isdigit(static_cast<unsigned char>(text[at]))) {
          std::size_t end = at;
          while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
          text.replace(at, end - at, tokens[static_cast<std::size_t>(rng.integer(0, 13))]);
        }
        break;
      default:  // insert a newline or NUL
        text.insert(at, 1, rng.integer(0, 1) ? '\n' : '\0');
    }
  }
  return text;
}

TEST(MeshReaderFuzz, MutatedFilesGiveAMeshOrAOneLineError) {
  Rng rng(2012);
  constexpr int iterations = 40000;
  int parsed = 0;
  for (int i = 0; i < iterations; ++i) {
    const std::string input = mutate(seeds()[static_cast<std::size_t>(i) % seeds().size()], rng);
    parsed += affinterp::fuzz::mesh_reader_one_input(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  }
  // Both outcomes must occur, or the mutations explore nothing.
  EXPECT_GT(parsed, iterations / 20);
  EXPECT_LT(parsed, iterations * 2 - iterations / 20);
}

TEST(MeshReaderFuzz, SeedsParse) {
  for (const std::string& text : seeds())
    EXPECT_EQ(affinterp::fuzz::mesh_reader_one_input(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
              1);
}

}  // namespace

}  // namespace mesh_reader_fuzz_test
