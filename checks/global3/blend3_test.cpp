// N-way blends and keyframes in 3D (theory/global3/blend3.hpp, keyframes3.hpp) on generated bars and tubes.
#include "theory/global3/blend3.hpp"
#include "checks/global3/meshes3.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/global3/keyframes3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <numbers>

namespace blend3_test {

using namespace affinterp::global3;
using affinterp::global::RefusedProblem;
using meshes3::box_diagonal;
constexpr double pi = std::numbers::pi;

/// Rest bar (length 10, width 1/10), then three poses: twisted by 1.8π, bent, bent and twisted back by −π.
std::vector<Mesh3> bar_poses() {
  const Mesh3 bar = meshes3::tetrahedral_bar(30, 10, 0.1);
  return {bar, meshes3::twisted(bar, 1.8 * pi, 10), meshes3::bent(bar, 10),
          meshes3::bent(meshes3::twisted(bar, -pi, 10), 10)};
}

std::vector<Mesh3> tube_poses() {
  const Mesh3 tube = meshes3::triangle_tube(8, 8, 4);
  return {tube, meshes3::twisted(tube, 1.5 * pi, 4), meshes3::bent(tube, 4)};
}

// w = e_k gives A_i(e_k) = exp([ω_{k,i}]×) exp(log S_{k,i}) = A_{k,i}, whose frame is pose k (E^F zero there).
TEST(Blend3, UnitWeightsGivePoses) {
  for (const std::vector<Mesh3>& poses : {bar_poses(), tube_poses()}) {
    const Blend3 blend(poses);
    for (std::size_t k = 0; k < poses.size(); ++k) {
      Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(poses.size()));
      w[static_cast<Eigen::Index>(k)] = 1;
      const double box = box_diagonal(poses[k].vertices);
      EXPECT_LT((blend.vertices_at(w) - poses[k].vertices).cwiseAbs().maxCoeff(), 1e-9 * box) << "pose " << k;
    }
  }
}

TEST(Blend3, SeparateRestMeshGivesPosesToo) {
  const std::vector<Mesh3> poses = bar_poses();
  const Blend3 blend(poses[2], {poses[0], poses[1], poses[3]});
  EXPECT_LT((blend.vertices_at(Eigen::Vector3d(0, 1, 0)) - poses[1].vertices).cwiseAbs().maxCoeff(),
            1e-9 * box_diagonal(poses[1].vertices));
}

// Two poses with weights (1 − t, t), rest = pose 0: the exp-log interpolation (Ω = tω, Λ = t log S) exactly.
TEST(Blend3, TwoPosesAreTheExpLogInterpolation) {
  const std::vector<Mesh3> poses = bar_poses();
  const Blend3 blend({poses[0], poses[1]});
  const Interpolation3 interpolation(poses[0], poses[1]);
  for (double t : {0.25, 0.5, 0.8})
    EXPECT_LT((blend.vertices_at(Eigen::Vector2d(1 - t, t)) - interpolation.vertices_at(t)).cwiseAbs().maxCoeff(),
              1e-12 * box_diagonal(poses[1].vertices));
}

// The 1.8π pose keeps its turns beyond π in the blend (the walk's root aligned with the rest's ω = 0, then
// carried along the bar): halfway between rest and it is the 0.9π bar, to a tenth of the width as
// Interpolation3.TwistedBarBeyondPiMatchesItsExactHalfwayPose measures.
TEST(Blend3, ConsistentBranchesSurviveTheRestPose) {
  const std::vector<Mesh3> poses = bar_poses();
  const Blend3 blend(poses);
  const Mesh3 halfway = meshes3::twisted(poses[0], 0.9 * pi, 10);
  const Eigen::Matrix3Xd v = blend.vertices_at(Eigen::Vector4d(0.5, 0.5, 0, 0));
  EXPECT_LT((v - halfway.vertices).colwise().norm().maxCoeff(), 0.1 * 0.1);
  EXPECT_GT(blend.rotation_logs(1).colwise().norm().maxCoeff(), 1.7 * pi);
}

// Poses through full turns: the thin bar at rest, twisted by 3π and by 5π. Each weight vector blends their
// logarithms, each pose's elements turned along its own carrier (rotation_carrier3.hpp), and gives the bar twisted
// by the weighted mean turn, 1.5π to 4π here, to within 0.26 widths in 30 boxes and 0.09 in 120.
TEST(Blend3, TwistsThroughFullTurnsBlendToTheirMeanTwist) {
  constexpr double length = 10, width = 0.1;
  for (const int boxes : {30, 120}) {
    const Mesh3 bar = meshes3::tetrahedral_bar(boxes, length, width);
    const Blend3 blend({bar, meshes3::twisted(bar, 3 * pi, length), meshes3::twisted(bar, 5 * pi, length)});
    for (const Eigen::Vector3d w : {Eigen::Vector3d(0, 0.5, 0.5), Eigen::Vector3d(0.5, 0.5, 0),
                                    Eigen::Vector3d(0.25, 0.25, 0.5), Eigen::Vector3d(0.5, 0, 0.5)}) {
      const Mesh3 exact = meshes3::twisted(bar, (3 * w[1] + 5 * w[2]) * pi, length);
      EXPECT_LT((blend.vertices_at(w) - exact.vertices).colwise().norm().maxCoeff(), 0.35 * width)
          << boxes << " boxes, w = " << w.transpose();
    }
  }
}

/// `mesh` turned rigidly by `angle` about the z axis through its barycentre.
Mesh3 turned(Mesh3 mesh, double angle) {
  const Eigen::Vector3d centre = mesh.vertices.rowwise().mean();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  mesh.vertices = (R * (mesh.vertices.colwise() - centre)).colwise() + centre;
  return mesh;
}

// Across poses: pose 1 turned by 0.9π, pose 2 by 1.1π (principal logarithm −0.9π). Pose 2's walk starts from the
// representative nearest pose 1's, 1.1π, so the even blend of the two is the half turn; with independent
// principal logarithms it would be the rest pose (0.9π − 0.9π = 0).
TEST(Blend3, PosesAreAlignedAcrossPoses) {
  const Mesh3 tube = meshes3::triangle_tube(4, 6, 3);
  const Blend3 blend({tube, turned(tube, 0.9 * pi), turned(tube, 1.1 * pi)});
  const Eigen::Matrix3Xd half_turn = turned(tube, pi).vertices;
  EXPECT_LT((blend.vertices_at(Eigen::Vector3d(0, 0.5, 0.5)) - half_turn).cwiseAbs().maxCoeff(),
            1e-9 * box_diagonal(half_turn));
  EXPECT_NEAR(blend.rotation_logs(2).col(0).norm(), 1.1 * pi, 1e-9);
  Blend3Options principal;
  principal.rotation_branch = affinterp::global::RotationBranch::principal;
  const Blend3 unaligned({tube, turned(tube, 0.9 * pi), turned(tube, 1.1 * pi)}, principal);
  EXPECT_LT((unaligned.vertices_at(Eigen::Vector3d(0, 0.5, 0.5)) - tube.vertices).cwiseAbs().maxCoeff(),
            1e-9 * box_diagonal(half_turn));
}

TEST(Blend3, RefusesWeightsOfWrongCountNonFiniteOrOffTheSimplex) {
  const std::vector<Mesh3> poses = tube_poses();
  const Blend3 blend(poses);
  EXPECT_THROW(blend.vertices_at(Eigen::Vector2d(0.5, 0.5)), RefusedProblem);
  EXPECT_THROW(blend.vertices_at(Eigen::Vector4d(0.25, 0.25, 0.25, 0.25)), RefusedProblem);
  EXPECT_THROW(blend.vertices_at(Eigen::Vector3d(0.5, NAN, 0.5)), RefusedProblem);
  EXPECT_THROW(blend.vertices_at(Eigen::Vector3d(1.5, -0.25, -0.25)), RefusedProblem);
  EXPECT_THROW(blend.vertices_at(Eigen::Vector3d(0.5, 0.5, 0.5)), RefusedProblem);
  EXPECT_THROW(blend.vertices_at(std::vector<Eigen::VectorXd>{Eigen::Vector3d(1, 0, 0), Eigen::Vector2d(1, 0)}),
               RefusedProblem);
  Blend3Options extrapolation;
  extrapolation.allow_extrapolation = true;
  const Blend3 extrapolating(poses, extrapolation);
  EXPECT_TRUE(extrapolating.vertices_at(Eigen::Vector3d(1.5, -0.25, -0.25)).allFinite());
  EXPECT_THROW(extrapolating.vertices_at(Eigen::Vector3d(INFINITY, 0, 0)), RefusedProblem);
  EXPECT_THROW(Blend3(std::vector<Mesh3>{poses[0]}), RefusedProblem);
  Blend3Options locus;  // a locus is a curve in time, which a blend has not
  locus.constraints.loci.push_back({0, Eigen::Matrix3Xd::Zero(3, 2), 1.0});
  EXPECT_THROW(Blend3(poses, locus), RefusedProblem);
}

TEST(Blend3, BatchIsOneAtATime) {
  const std::vector<Mesh3> poses = bar_poses();
  const Blend3 blend(poses);
  const std::vector<Eigen::VectorXd> weights{Eigen::Vector4d(0.1, 0.2, 0.3, 0.4), Eigen::Vector4d(0, 0, 1, 0),
                                             Eigen::Vector4d(0.25, 0.25, 0.25, 0.25)};
  const std::vector<Eigen::Matrix3Xd> batch = blend.vertices_at(weights);
  for (std::size_t f = 0; f < weights.size(); ++f) EXPECT_EQ(batch[f], blend.vertices_at(weights[f]));
}

TEST(Keyframes3, HitEachPoseAtItsKeyTime) {
  const std::vector<Mesh3> poses = bar_poses();
  const std::vector<double> keys{0, 0.5, 0.75, 2};
  const Keyframes3 keyframes(poses, keys);
  for (std::size_t k = 0; k < poses.size(); ++k)
    EXPECT_LT((keyframes.vertices_at(keys[k]) - poses[k].vertices).cwiseAbs().maxCoeff(),
              1e-9 * box_diagonal(poses[k].vertices))
        << "key " << k;
  EXPECT_EQ(keyframes.weights_at(0.625), Eigen::Vector4d(0, 0.5, 0.5, 0));
  const std::vector<Eigen::Matrix3Xd> batch = keyframes.vertices_at(std::vector<double>{0.1, 0.6, 1.9});
  EXPECT_EQ(batch[1], keyframes.vertices_at(0.6));
}

// C⁰ at the keys: the frames just before and just after a key approach the pose.
TEST(Keyframes3, AreContinuousAtTheKeys) {
  const std::vector<Mesh3> poses = bar_poses();
  const Keyframes3 keyframes(poses, {0, 1, 2, 3});
  for (double key : {1.0, 2.0}) {
    const double jump = (keyframes.vertices_at(key + 1e-6) - keyframes.vertices_at(key - 1e-6)).cwiseAbs().maxCoeff();
    EXPECT_LT(jump, 1e-4 * box_diagonal(poses[0].vertices));
  }
}

TEST(Keyframes3, RefuseBadKeyTimesAndTimesOutside) {
  const std::vector<Mesh3> poses = tube_poses();
  EXPECT_THROW(Keyframes3(poses, {0, 1}), RefusedProblem);
  EXPECT_THROW(Keyframes3(poses, {0, 1, 1}), RefusedProblem);
  EXPECT_THROW(Keyframes3(poses, {0, NAN, 1}), RefusedProblem);
  const Keyframes3 keyframes(poses, {0, 1, 2});
  EXPECT_THROW(keyframes.vertices_at(-0.1), std::out_of_range);
  EXPECT_THROW(keyframes.vertices_at(2.1), std::out_of_range);
  EXPECT_THROW(keyframes.vertices_at(NAN), std::out_of_range);
}

}  // namespace blend3_test
