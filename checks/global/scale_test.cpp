// The engine at scale: the barycentre and the default gauge handled exactly, so that a strip
// rolled into a spiral interpolates at every size and in any units; the batch vertices_at(times) equal to
// the frames one by one; and the two sparse back-ends (sparse_factor.hpp) giving the same solutions.
#include "checks/global/strip.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/sparse_factor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <vector>

namespace affinterp::global::scale_test {
namespace {

using testing::box_size;
using testing::cli_options;
using testing::spiral;
using testing::Spiral;

const Energy all_energies[] = {Energy::F, Energy::S, Energy::R, Energy::blend};

/// −½ G⁻¹ u by a dense solve of the whole form: the Appendix's minimiser, with no elimination or grounding.
Eigen::Matrix2Xd dense_minimiser(const Interpolation& interpolation, double t) {
  const FrameQuadratic q = interpolation.quadratic_at(t);
  const Eigen::VectorXd v = q.G.ldlt().solve(-0.5 * q.u);
  return Eigen::Map<const Eigen::Matrix2Xd>(v.data(), 2, v.size() / 2);
}

TEST(Scale, SpiralMatchesTheDenseMinimiserWithEveryEnergy) {
  const Spiral s = spiral(40, 4);
  const double box = box_size(s.source, s.target);
  for (const Energy energy : all_energies) {
    const Interpolation interpolation(s.source, s.target, cli_options(energy, s));
    for (const double t : {0.0, 0.3, 0.5, 1.0})
      EXPECT_LT((interpolation.vertices_at(t) - dense_minimiser(interpolation, t)).cwiseAbs().maxCoeff(), 1e-9 * box)
          << to_string(energy) << " t " << t;
  }
}

// E^F, E^R and the blend with area weights have the units of the constraints (length²), so the minimiser is
// the same shape in any units. E^S does not: Σ_k ‖s R_δ A p_k − B p_k‖² is in length² per triangle, times the
// area, against the gauge edge's length²; in micrometres the edge outweighs it by 10¹² and G is numerically
// singular (refused). Left out here: an open limitation of E^S under the default gauge.
TEST(Scale, SpiralInAnyUnitsIsTheSameShapeScaled) {
  const Spiral unit = spiral(60, 6);
  for (const Energy energy : {Energy::F, Energy::R, Energy::blend}) {
    const Eigen::Matrix2Xd reference =
        Interpolation(unit.source, unit.target, cli_options(energy, unit)).vertices_at(0.5);
    for (const double scale : {1e-6, 1e6}) {
      const Spiral s = spiral(60, 6, 18.8 * scale);
      const Eigen::Matrix2Xd v = Interpolation(s.source, s.target, cli_options(energy, s)).vertices_at(0.5);
      EXPECT_LT((v / scale - reference).cwiseAbs().maxCoeff(), 1e-9 * box_size(unit.source, unit.target))
          << to_string(energy) << " scale " << scale;
    }
  }
}

// From 10 triangles (a strip of 5 × 1 quads) to 10,000 (200 × 25): every size is accepted,
// and the barycentre follows its straight locus, which the elimination imposes exactly.
TEST(Scale, SpiralsOfEverySizeAreAccepted) {
  for (const auto& [cols, rows] : {std::pair{5, 1}, {20, 2}, {200, 25}, {160, 20}}) {
    const Spiral s = spiral(cols, rows);
    for (const Energy energy : {Energy::F, Energy::R}) {
      const Interpolation interpolation(s.source, s.target, cli_options(energy, s));
      const Eigen::Matrix2Xd v = interpolation.vertices_at(0.5);
      const Eigen::Vector2d expected = (s.source.vertices.rowwise().mean() + s.target.vertices.rowwise().mean()) / 2;
      EXPECT_LT((v.rowwise().mean() - expected).norm(), 1e-9 * box_size(s.source, s.target))
          << to_string(energy) << " " << cols << " x " << rows;
    }
  }
}

TEST(Scale, BatchFramesAreTheFramesOneByOne) {
  const Spiral s = spiral(30, 3);
  const std::vector<double> times = {0.0, 0.25, 0.5, 0.5, 0.9, 1.0, 0.1};
  for (const Energy energy : all_energies) {
    const Interpolation interpolation(s.source, s.target, cli_options(energy, s));
    const std::vector<Eigen::Matrix2Xd> batch = interpolation.vertices_at(times);
    ASSERT_EQ(batch.size(), times.size());
    for (std::size_t k = 0; k < times.size(); ++k)
      EXPECT_TRUE(batch[k] == interpolation.vertices_at(times[k])) << to_string(energy) << " frame " << k;
  }
  const Interpolation interpolation(s.source, s.target, cli_options(Energy::R, s));
  EXPECT_THROW(interpolation.vertices_at(std::vector<double>{0.5, 1.5}), std::out_of_range);
  EXPECT_TRUE(interpolation.vertices_at(std::vector<double>{}).empty());
}

/// A 2D grid Laplacian plus a diagonal shift (Hermitian positive definite), lower triangle, with complex
/// off-diagonal phases when Scalar is complex.
template <class Scalar>
Eigen::SparseMatrix<Scalar> grid_matrix(int side) {
  std::vector<Eigen::Triplet<Scalar>> entries;
  auto at = [side](int i, int j) { return i * side + j; };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      entries.emplace_back(at(i, j), at(i, j), Scalar(4.5));
      if (i + 1 < side) entries.emplace_back(at(i + 1, j), at(i, j), Scalar(-1));
      if (j + 1 < side) {
        Scalar w(-1);
        if constexpr (!std::is_same_v<Scalar, double>) w = std::polar(1.0, 0.1 * (i - j));
        entries.emplace_back(at(i, j + 1), at(i, j), w);
      }
    }
  Eigen::SparseMatrix<Scalar> K(side * side, side * side);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

template <class Scalar>
void expect_back_ends_agree() {
  const Eigen::SparseMatrix<Scalar> K = grid_matrix<Scalar>(30);
  using Block = typename SparseFactor<Scalar>::Block;
  const Block B = Block::Random(K.rows(), 3);
  const Eigen::SparseMatrix<Scalar> full = K.template selfadjointView<Eigen::Lower>();
  std::vector<SparseBackEnd> back_ends = {SparseBackEnd::simplicial};
  if (has_cholmod()) back_ends.push_back(SparseBackEnd::cholmod);
  for (const SparseBackEnd back_end : back_ends) {
    auto factor = make_sparse_factor<Scalar>(back_end);
    factor->analyse(K);
    ASSERT_TRUE(factor->factorise(K, 1));
    Block X = B, on_two_threads = B;
    factor->clone()->solve_in_place(X, 1);  // a clone holds the same factor
    factor->solve_in_place(on_two_threads, 2);
    EXPECT_LT((Block(full * X) - B).cwiseAbs().maxCoeff(), 1e-12) << static_cast<int>(back_end);
    EXPECT_TRUE(X == on_two_threads) << static_cast<int>(back_end);
  }
}

TEST(Scale, BackEndsSolveAlike) {
  expect_back_ends_agree<double>();
  expect_back_ends_agree<std::complex<double>>();
}

TEST(Scale, BackEndsRefuseASingularMatrix) {
  Eigen::SparseMatrix<double> K = grid_matrix<double>(10);
  for (int s = K.outerIndexPtr()[0]; s < K.outerIndexPtr()[1]; ++s) K.valuePtr()[s] = 0;  // row and column 0
  std::vector<SparseBackEnd> back_ends = {SparseBackEnd::simplicial};
  if (has_cholmod()) back_ends.push_back(SparseBackEnd::cholmod);
  for (const SparseBackEnd back_end : back_ends) {
    auto factor = make_sparse_factor<double>(back_end);
    factor->analyse(K);
    EXPECT_FALSE(factor->factorise(K, 1)) << static_cast<int>(back_end);
  }
}

}  // namespace
}  // namespace affinterp::global::scale_test
