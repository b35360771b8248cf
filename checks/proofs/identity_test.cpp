#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/exact_grid.hpp"
#include "experiments/proofs/ginac_scalar.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <Eigen/LU>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace affinterp::proofs::identity_test {
namespace {

const GiNaC::symbol x("x"), y("y"), z("z");

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ExactGrid, AcceptsARightIdentityAndBoundsItsDegree) {
  const GridVerdict v = grid_check(GiNaC::pow(x + y, 3), GiNaC::pow(x, 3) + 3 * x * x * y + 3 * x * y * y + y * y * y);
  EXPECT_TRUE(v.zero);
  ASSERT_EQ(v.degree_bounds.size(), 2u);
  EXPECT_EQ(v.degree_bounds[0].second, 3u);
  EXPECT_EQ(v.degree_bounds[1].second, 3u);
  EXPECT_EQ(v.total_degree, 3u);
  EXPECT_EQ(v.grid_points, 10u);  // (a, b) in {0..3}² with a + b ≤ 3
  EXPECT_EQ(v.evaluated, 10u);
}

TEST(ExactGrid, FindsAWrongIdentityNonZero) {
  const GridVerdict v = grid_check(GiNaC::pow(x + y, 2), x * x + x * y + y * y);
  EXPECT_FALSE(v.zero);
  EXPECT_EQ(v.witness.at("x"), 1u);  // the first grid point with xy ≠ 0
  EXPECT_EQ(v.witness.at("y"), 1u);
  EXPECT_EQ(v.witness_value, "1");
}

TEST(ExactGrid, DecidesRationalIdentitiesThroughTheirNumerator) {
  // 1/(x − 1) − 1/(x + 1) = 2/(x² − 1), and a wrong variant.
  EXPECT_TRUE(grid_check(1 / (x - 1) - 1 / (x + 1), 2 / (x * x - 1)).zero);
  EXPECT_FALSE(grid_check(1 / (x - 1) - 1 / (x + 1), 2 / (x * x + 1)).zero);
  // A function is an independent variable: exp(x)/exp(x)... is not cancelled by the grid, but still 1.
  EXPECT_TRUE(grid_check(GiNaC::exp(x) * (x + 1) / (x + 1), GiNaC::exp(x)).zero);
}

TEST(ExactGrid, RefusesWhatIsNotRational) {
  EXPECT_THROW(grid_check(GiNaC::sqrt(x), x), std::invalid_argument);
  // A denominator that is the zero polynomial, unexpanded: both sides are nowhere defined.
  const GiNaC::ex zero_polynomial = GiNaC::pow(x + 1, 2) - x * x - 2 * x - 1;
  EXPECT_THROW(grid_check(1 / zero_polynomial, x), std::invalid_argument);
  EXPECT_THROW(grid_check(x / zero_polynomial, x / zero_polynomial), std::invalid_argument);
}

// The grid bound is sufficient: a polynomial of degree ≤ d_i in each variable and of total degree ≤ T that is
// nonzero somewhere is found nonzero on S = {a ≤ d, Σ a ≤ T}, even one that vanishes on every other point of S.
RC_GTEST_PROP(ExactGrid, GridOfTheBoundDetectsEveryNonzeroPolynomial, ()) {
  {
    const unsigned dx = *rc::gen::inRange(1u, 4u), dy = *rc::gen::inRange(0u, 4u);
    const int c = *rc::gen::nonZero<int>();
    GiNaC::ex p = c;
    for (unsigned i = 0; i < dx; ++i) p *= x - static_cast<int>(i);
    for (unsigned j = 0; j < dy; ++j) p *= y - static_cast<int>(j);
    // p has degree dx in x, dy in y and vanishes on {0..dx−1} × {0..dy−1} and far more: only the point
    // (dx, dy) of the grid {0..dx} × {0..dy} shows it is nonzero.
    const GridVerdict v = grid_check(p, GiNaC::ex(0));
    RC_ASSERT(!v.zero);
    RC_ASSERT(v.witness.at("x") == dx);
    if (dy > 0) RC_ASSERT(v.witness.at("y") == dy);
  }
}

// Grid zero ⇔ expansion zero, for a product against its expansion with one coefficient changed or not.
RC_GTEST_PROP(ExactGrid, AgreesWithExpansionOnRandomPolynomials, ()) {
  {
    const int a = *rc::gen::inRange(-3, 4), b = *rc::gen::inRange(-3, 4), change = *rc::gen::inRange(0, 3);
    const GiNaC::ex p = GiNaC::pow(x + a * y, 2) * (z - b), expanded = p.expand() + change * x * y * z;
    RC_ASSERT(grid_check(p, expanded).zero == (change == 0));
  }
}

TEST(Identity, BothCheckersAcceptARightIdentityAndWriteRerunnableFiles) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "proofs-identity-test";
  std::filesystem::remove_all(dir);
  // (x I + y J) for J = R_{π/2} over GiNaC: Eigen's algebra on symbols.
  SymbolicMatrix<2, 2> C;
  C << x, -y, y, x;
  const GiNaC::ex det = C.determinant();
  const ProofSentence s =
      prove_identity({"det-similarity", "det(xI + yJ) = x² + y²", det, x * x + y * y}, {dir, "proofs/test"});
  EXPECT_EQ(s.result, "zero");
  ASSERT_EQ(s.runs.size(), 2u);
  EXPECT_EQ(s.runs[0].tool, "ginac");
  EXPECT_EQ(s.runs[1].tool, "exact-grid");
  EXPECT_EQ(s.runs[0].file, "proofs/test/det-similarity.ginsh");
  EXPECT_EQ(read(dir / "det-similarity.ginsh.out"), "1\n");
  EXPECT_NE(read(dir / "det-similarity.grid.out").find("result: zero"), std::string::npos);
  // The script is ginsh's own input: rerun it where GiNaC's shell is installed.
  if (std::system("command -v ginsh > /dev/null 2>&1") == 0) {
    const std::string out = (dir / "ginsh.txt").string();
    ASSERT_EQ(std::system(("ginsh " + (dir / "det-similarity.ginsh").string() + " > " + out).c_str()), 0);
    EXPECT_EQ(read(out), "1\n");
  }
}

TEST(Identity, BothCheckersFindAWrongIdentityNonZero) {
  const ProofSentence s =
      prove_identity({"wrong", "(x + y)² = x² + y² (wrong)", GiNaC::pow(x + y, 2), x * x + y * y}, {{}, "proofs/t"});
  EXPECT_EQ(s.result, "non-zero");
  EXPECT_EQ(s.runs[0].result, "non-zero");
  EXPECT_EQ(s.runs[1].result, "non-zero");
}

TEST(Identity, ComparesMatricesEntryByEntry) {
  GiNaC::matrix a{{x, y}, {y, x}}, b{{x, y}, {y, x + 0 * z}}, c{{x, y}, {x, y}};
  EXPECT_EQ(prove_identity({"same", "", a, b}, {{}, "proofs/t"}).result, "zero");
  EXPECT_EQ(prove_identity({"differ", "", a, c}, {{}, "proofs/t"}).result, "non-zero");
}

TEST(Identity, RefusesTwoSymbolsOfOneName) {
  const GiNaC::symbol other_x("x");
  EXPECT_THROW(prove_identity({"clash", "", x, other_x}, {{}, "proofs/t"}), std::invalid_argument);
}

}  // namespace
}  // namespace affinterp::proofs::identity_test
