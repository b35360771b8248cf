// Our up-looking LDLᴴ (theory/global/simplicial_factor.hpp, ldl_symbolic.hpp) against Eigen's SimplicialLDLT on
// Hermitian positive definite grids, real and complex: the same solution to rounding, the same factor on one
// thread and on two (rows of two groups of subtrees side by side), the upper triangle ignored, a singular or
// indefinite matrix refused, and nothing of a refused factorisation left in the next one; two matrices of one
// pattern factorised in one pass (factorise_two) give the factors each gives alone, bit for bit.
#include "theory/global/simplicial_factor.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <complex>
#include <memory>
#include <random>
#include <vector>

namespace affinterp::global::simplicial_factor_test {
namespace {

/// A side × side grid's Laplacian, its edges weighted by random complex (or real) numbers of modulus about 1,
/// plus `shift` on the diagonal: Hermitian, positive definite for shift > 0. Both triangles stored.
template <class Scalar>
Eigen::SparseMatrix<Scalar> grid(int side, double shift, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = side * side;
  std::vector<Eigen::Triplet<Scalar>> entries;
  std::vector<double> degree(static_cast<std::size_t>(n), shift);
  auto edge = [&](int a, int b) {
    Scalar w;
    if constexpr (std::is_same_v<Scalar, double>)
      w = 1.0 + 0.5 * uniform(random);
    else
      w = std::polar(1.0 + 0.5 * uniform(random), 3.0 * uniform(random));
    entries.emplace_back(a, b, -w), entries.emplace_back(b, a, -Eigen::numext::conj(w));
    degree[static_cast<std::size_t>(a)] += std::abs(w), degree[static_cast<std::size_t>(b)] += std::abs(w);
  };
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      if (c + 1 < side) edge(r * side + c, r * side + c + 1);
      if (r + 1 < side) edge(r * side + c, (r + 1) * side + c);
    }
  for (int k = 0; k < n; ++k) entries.emplace_back(k, k, degree[static_cast<std::size_t>(k)]);
  Eigen::SparseMatrix<Scalar> K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

template <class Scalar>
using Block = typename SparseFactor<Scalar>::Block;

template <class Scalar>
Block<Scalar> right_hand_sides(Eigen::Index n) {
  Block<Scalar> B(n, 2);
  for (Eigen::Index k = 0; k < n; ++k) B.row(k) << Scalar(std::sin(0.1 * k)), Scalar(1.0 + 0.01 * k);
  return B;
}

template <class Scalar>
Block<Scalar> solved(const SimplicialFactor<Scalar>& factor, Block<Scalar> X, std::size_t threads) {
  factor.solve_in_place(X, threads);
  return X;
}

template <class Scalar>
class SimplicialFactorTest : public ::testing::Test {};
using Scalars = ::testing::Types<double, std::complex<double>>;
TYPED_TEST_SUITE(SimplicialFactorTest, Scalars);

TYPED_TEST(SimplicialFactorTest, SolvesAsEigensLdltOnOneThreadAndTwoAlike) {
  using Scalar = TypeParam;
  const Eigen::SparseMatrix<Scalar> K = grid<Scalar>(24, 0.01, 7);
  const Eigen::SparseMatrix<Scalar> lower = K.template triangularView<Eigen::Lower>();
  ASSERT_TRUE(ldl_symbolic(lower.cols(), lower.outerIndexPtr(), lower.innerIndexPtr()).subtrees);  // two groups
  const Block<Scalar> B = right_hand_sides<Scalar>(K.rows());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>, Eigen::Lower> eigen(lower);
  ASSERT_EQ(eigen.info(), Eigen::Success);
  const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> expected = eigen.solve(B);

  for (const auto& given : {K, lower}) {  // the upper triangle, where stored, is not read
    SimplicialFactor<Scalar> factor;
    factor.analyse(given);
    ASSERT_TRUE(factor.factorise(given, 1));
    const Block<Scalar> one = solved(factor, B, 1);
    EXPECT_LT((one - expected).norm(), 1e-12 * expected.norm());
    ASSERT_TRUE(factor.factorise(given, 2));
    EXPECT_EQ(solved(factor, B, 2), one);  // the same factor, the same solve, whatever the threads
  }
}

TYPED_TEST(SimplicialFactorTest, RefusesASingularMatrixAndLeavesNothingOfIt) {
  using Scalar = TypeParam;
  Eigen::SparseMatrix<Scalar> K = grid<Scalar>(12, 0.01, 11);
  const Block<Scalar> B = right_hand_sides<Scalar>(K.rows());
  SimplicialFactor<Scalar> fresh;
  fresh.analyse(K);
  ASSERT_TRUE(fresh.factorise(K, 2));
  const Block<Scalar> expected = solved(fresh, B, 1);

  SimplicialFactor<Scalar> factor;
  factor.analyse(K);
  Eigen::SparseMatrix<Scalar> singular = K;  // vertex 5 cut off, its pattern kept: a zero pivot, 0/0 beyond it
  for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(singular, 5); it; ++it) {
    it.valueRef() = 0;
    singular.coeffRef(5, it.index()) = 0;
  }
  EXPECT_FALSE(factor.factorise(singular, 2));
  if constexpr (std::is_same_v<Scalar, double>) {  // no shift: the constants are the real Laplacian's kernel
    EXPECT_FALSE(factor.factorise(grid<Scalar>(12, 0.0, 11), 1));
  }
  ASSERT_TRUE(factor.factorise(K, 2));
  EXPECT_EQ(solved(factor, B, 1), expected);
}

TYPED_TEST(SimplicialFactorTest, ReadsAMatrixNotCompressed) {
  using Scalar = TypeParam;
  const Eigen::SparseMatrix<Scalar> K = grid<Scalar>(10, 0.5, 3);
  Eigen::SparseMatrix<Scalar> loose = K;
  loose.uncompress();
  SimplicialFactor<Scalar> factor, reference;
  factor.analyse(loose), reference.analyse(K);
  ASSERT_TRUE(factor.factorise(loose, 1));
  ASSERT_TRUE(reference.factorise(K, 1));
  const Block<Scalar> B = right_hand_sides<Scalar>(K.rows());
  EXPECT_EQ(solved(factor, B, 1), solved(reference, B, 1));
}

TYPED_TEST(SimplicialFactorTest, FactorisesTwoInOnePassAsEachAlone) {
  using Scalar = TypeParam;
  const Eigen::SparseMatrix<Scalar> K = grid<Scalar>(24, 0.01, 7), K_other = grid<Scalar>(24, 0.3, 8);  // one pattern
  const Block<Scalar> B = right_hand_sides<Scalar>(K.rows());
  SimplicialFactor<Scalar> alone;
  alone.analyse(K);
  ASSERT_TRUE(alone.factorise(K, 2));
  const Block<Scalar> expected = solved(alone, B, 1);
  ASSERT_TRUE(alone.factorise(K_other, 1));
  const Block<Scalar> expected_other = solved(alone, B, 1);

  SimplicialFactor<Scalar> factor;
  factor.analyse(K);
  const std::unique_ptr<SparseFactor<Scalar>> other = factor.clone();  // shares the analysis: one pass
  ASSERT_TRUE(factor.two_in_one_pass());
  for (int pass = 0; pass < 2; ++pass) {  // the second reuses the first's rows, which must come back clean
    ASSERT_TRUE(factor.factorise_two(K, *other, K_other));
    EXPECT_EQ(solved(factor, B, 1), expected);
    Block<Scalar> X = B;
    other->solve_in_place(X, 2);
    EXPECT_EQ(X, expected_other);
  }
  SimplicialFactor<Scalar> analysed_apart;  // not sharing the analysis: one after the other, the same factors
  analysed_apart.analyse(K);
  ASSERT_TRUE(factor.factorise_two(K_other, analysed_apart, K));
  EXPECT_EQ(solved(analysed_apart, B, 1), expected);
  EXPECT_EQ(solved(factor, B, 1), expected_other);

  Eigen::SparseMatrix<Scalar> singular = K;  // vertex 5 cut off: refused, whichever of the two it is
  for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(singular, 5); it; ++it) {
    it.valueRef() = 0;
    singular.coeffRef(5, it.index()) = 0;
  }
  EXPECT_FALSE(factor.factorise_two(K, *other, singular));
  EXPECT_FALSE(factor.factorise_two(singular, *other, K));
  ASSERT_TRUE(factor.factorise_two(K, *other, K_other));
  EXPECT_EQ(solved(factor, B, 1), expected);
}

}  // namespace
}  // namespace affinterp::global::simplicial_factor_test
