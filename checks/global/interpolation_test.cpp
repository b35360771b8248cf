// The global interpolation engine (Kaji §4) against a dense reference solve, its end points, the rotation
// branch choice and its refusals.
#include "theory/global/interpolation.hpp"
#include "checks/global/strip.hpp"
#include "theory/global/local_paths.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Dense>

#include <numbers>
#include <thread>
#include <vector>

namespace affinterp::global::interpolation_test {
namespace {

using testing::bent;
using testing::strip;

InterpolationOptions with(Energy energy, Constraints constraints) {
  InterpolationOptions options;
  options.energy = energy;
  options.constraints = std::move(constraints);
  return options;
}

Constraints two_pins(Eigen::Index a, Eigen::Index b) { return {{{a, 1.0}, {b, 1.0}}, {}, {}, {}}; }

/// −½ G⁻¹ u by a dense solve: the Appendix's minimiser, independent of the sparse machinery.
Eigen::Matrix2Xd dense_minimiser(const Interpolation& interpolation, double t) {
  const FrameQuadratic q = interpolation.quadratic_at(t);
  const Eigen::VectorXd v = q.G.ldlt().solve(-0.5 * q.u);
  return Eigen::Map<const Eigen::Matrix2Xd>(v.data(), 2, v.size() / 2);
}

const Energy all_energies[] = {Energy::F, Energy::S, Energy::R, Energy::blend};

TEST(Interpolation, EndPointsAreSourceAndTarget) {
  const Mesh P = strip(4, 2), Q = bent(P, 1.5);
  for (const Energy energy : all_energies) {
    const Interpolation interpolation(P, Q, with(energy, two_pins(0, 14)));
    EXPECT_LT((interpolation.vertices_at(0) - P.vertices).cwiseAbs().maxCoeff(), 1e-9) << to_string(energy);
    EXPECT_LT((interpolation.vertices_at(1) - Q.vertices).cwiseAbs().maxCoeff(), 1e-9) << to_string(energy);
  }
}

TEST(Interpolation, SparseSolveMatchesDenseMinimiser) {
  const Mesh P = strip(6, 1), Q = bent(P, 4.0);
  for (const Energy energy : all_energies)
    for (const bool symmetric : {false, true})
      for (const bool area : {false, true}) {
        InterpolationOptions options = with(energy, two_pins(0, 13));
        options.symmetric = symmetric, options.area_weighted = area;
        options.constraints.edges.push_back({1, 2, EdgeDirection::Path::local_homotopy, 0.5});
        options.constraints.barycentre = BarycentreLocus{};
        const Interpolation interpolation(P, Q, options);
        for (const double t : {0.25, 0.5, 0.8})
          EXPECT_LT((interpolation.vertices_at(t) - dense_minimiser(interpolation, t)).cwiseAbs().maxCoeff(), 1e-9)
              << to_string(energy) << " symmetric " << symmetric << " area " << area << " t " << t;
      }
}

TEST(Interpolation, BarycentreAloneFixesTranslationOfEF) {
  const Mesh P = strip(3, 1), Q = bent(P, 1.0);
  Constraints constraints;
  constraints.barycentre = BarycentreLocus{};
  const Interpolation interpolation(P, Q, with(Energy::F, constraints));
  const Eigen::Matrix2Xd v = interpolation.vertices_at(0.5);
  EXPECT_LT((v - dense_minimiser(interpolation, 0.5)).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::Vector2d expected = (P.vertices.rowwise().mean() + Q.vertices.rowwise().mean()) / 2;
  EXPECT_LT((v.rowwise().mean() - expected).norm(), 1e-9);
}

TEST(Interpolation, FrobeniusIsFactoredOnceAndSimilarityIsNot) {
  const Mesh P = strip(2, 1), Q = bent(P, 1.0);
  EXPECT_TRUE(Interpolation(P, Q, with(Energy::F, two_pins(0, 5))).factored_once());
  EXPECT_FALSE(Interpolation(P, Q, with(Energy::R, two_pins(0, 5))).factored_once());
  InterpolationOptions rigid = with(Energy::blend, two_pins(0, 5));
  rigid.blend_weight = 1.0;
  EXPECT_TRUE(Interpolation(P, Q, rigid).factored_once());
}

TEST(Interpolation, ConsistentBranchUnwrapsACoil) {
  const Mesh P = strip(12, 1), Q = bent(P, 3 * std::numbers::pi);  // coils one and a half turns
  InterpolationOptions options = with(Energy::F, two_pins(0, 13));
  const Eigen::VectorXd theta = Interpolation(P, Q, options).rotation_angles();
  EXPECT_GT(theta.maxCoeff(), 2 * std::numbers::pi);
  options.rotation_branch = RotationBranch::principal;
  EXPECT_LE(Interpolation(P, Q, options).rotation_angles().maxCoeff(), std::numbers::pi + 1e-12);
}

TEST(Interpolation, RefusesIllPosedProblems) {
  const Mesh P = strip(2, 1), Q = bent(P, 1.0);
  EXPECT_THROW(Interpolation(P, Q, with(Energy::F, {})), RefusedProblem);
  try {
    Interpolation(P, Q, with(Energy::R, {{{0, 1.0}}, {}, {}, {}}));
    ADD_FAILURE() << "E^R with one pinned vertex was accepted";
  } catch (const RefusedProblem& e) {
    EXPECT_NE(std::string(e.what()).find("collapse"), std::string::npos) << e.what();
  }
  // One pin and an edge direction fix translation, rotation and scale.
  Constraints pin_and_edge{{{0, 1.0}}, {}, {{0, 1, EdgeDirection::Path::local_homotopy, 1.0}}, {}};
  EXPECT_NO_THROW(Interpolation(P, Q, with(Energy::R, pin_and_edge)));
  Mesh flipped = Q;
  flipped.vertices.row(0) *= -1;
  EXPECT_THROW(Interpolation(P, flipped, with(Energy::F, two_pins(0, 5))), RefusedProblem);
  Mesh other = Q;
  other.triangles.col(0) = other.triangles.col(0).reverse().eval();
  EXPECT_THROW(Interpolation(P, other, with(Energy::F, two_pins(0, 5))), RefusedProblem);
  EXPECT_THROW(Interpolation(P, Q, with(Energy::F, two_pins(0, 99))), RefusedProblem);
  EXPECT_THROW(Interpolation(P, Q, with(Energy::F, two_pins(0, 5))).vertices_at(1.5), std::out_of_range);
}

// vertices_at is const: frames computed by several threads at once on one object (E^R, refactorised per
// frame in the object's workspace) are bit for bit the frames computed one after another.
TEST(Interpolation, VerticesAtIsSafeToCallConcurrently) {
  const Mesh P = strip(8, 2), Q = bent(P, 2.0);
  const Interpolation interpolation(P, Q, with(Energy::R, two_pins(0, P.vertex_count() - 1)));
  ASSERT_FALSE(interpolation.factored_once());
  constexpr int frames = 8;
  std::vector<Eigen::Matrix2Xd> alone, together(frames);
  for (int k = 0; k < frames; ++k) alone.push_back(interpolation.vertices_at(k / (frames - 1.0)));
  std::vector<std::thread> threads;
  for (int k = 0; k < frames; ++k)
    threads.emplace_back(
        [&, k] { together[static_cast<std::size_t>(k)] = interpolation.vertices_at(k / (frames - 1.0)); });
  for (std::thread& thread : threads) thread.join();
  for (std::size_t k = 0; k < frames; ++k) EXPECT_TRUE(alone[k] == together[k]) << "frame " << k;
}

RC_GTEST_PROP(Interpolation, RandomTargetsMatchDenseMinimiser, ()) {
  const int cols = *rc::gen::inRange(1, 5), rows = *rc::gen::inRange(1, 3);
  const Mesh P = strip(cols, rows);
  Mesh Q = P;
  for (Eigen::Index k = 0; k < Q.vertex_count(); ++k)
    Q.vertices.col(k) += Eigen::Vector2d(*rc::gen::inRange(-20, 21), *rc::gen::inRange(-20, 21)) / 100.0;
  const double turn = *rc::gen::inRange(1, 11) / 10.0 * cols / (rows + 0.5);  // radius > rows + 0.5
  Q = bent(Q, turn);
  for (Eigen::Index i = 0; i < Q.triangle_count(); ++i) RC_PRE(Q.doubled_signed_area(i) > 0.05);
  const Energy energy = *rc::gen::element(Energy::F, Energy::S, Energy::R, Energy::blend);
  const Interpolation interpolation(P, Q, with(energy, two_pins(0, P.vertex_count() - 1)));
  const double t = *rc::gen::inRange(0, 11) / 10.0;
  RC_ASSERT((interpolation.vertices_at(t) - dense_minimiser(interpolation, t)).cwiseAbs().maxCoeff() < 1e-8);
}

}  // namespace
}  // namespace affinterp::global::interpolation_test

namespace affinterp::global {
namespace {

TEST(LocalPaths, ExpMatchesTheLocalTheorysHomotopyOnEveryBranch) {
  const std::vector<Eigen::Matrix2d> A = {(Eigen::Matrix2d() << 2, 1, -0.5, 0.7).finished(),
                                          (Eigen::Matrix2d() << -1, -0.2, 0.3, -2).finished(),
                                          Eigen::Matrix2d::Identity()};
  for (const double k : {-1.0, 0.0, 2.0}) {
    Eigen::VectorXd theta(3);
    for (int i = 0; i < 3; ++i)
      theta[i] = principal_polar_angle(A[static_cast<std::size_t>(i)]) + 2 * std::numbers::pi * k;
    const LocalPaths paths(A, LocalHomotopy::exp, theta);
    for (int i = 0; i < 3; ++i) {
      const local::Polar<double> polar = local::polar_decomposition<double>(A[static_cast<std::size_t>(i)]);
      const local::ExpLogHomotopy<double> reference(theta[i], polar.S);
      for (const double t : {-0.5, 0.0, 0.3, 1.0, 1.7})
        EXPECT_LT((paths.at(i, t) - reference(t)).cwiseAbs().maxCoeff(), 1e-12)
            << "i " << i << " t " << t << " k " << k;
    }
  }
}

}  // namespace
}  // namespace affinterp::global
