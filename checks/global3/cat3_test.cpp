// The 3D engine on real data: the cat poses of Sumner and Popović ("Deformation transfer for triangle meshes",
// SIGGRAPH 2004), ten poses of one triangle mesh (7,207 vertices, 14,410 triangles), in ../shared/data when
// present (skipped otherwise). Exp-log from cat-0 to each other pose: frames continuous at 21 frames (the tail,
// turned by up to 180° in some poses, among them), the ends the poses, few folded triangles, nearly all of them at
// triangles the target pose itself folds.
#include "checks/global3/meshes3.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/global3/target_folds3.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cat3_test {

using namespace affinterp::global3;

std::filesystem::path cat_folder() {
  for (const char* candidate : {"/work/shared/data/meshes3d/cat", "../shared/data/meshes3d/cat"})
    if (std::filesystem::exists(std::filesystem::path(candidate) / "cat-0.off")) return candidate;
  return {};
}

std::vector<Mesh3> cat_poses() {
  std::vector<Mesh3> poses;
  const std::filesystem::path folder = cat_folder();
  if (folder.empty()) return poses;
  for (int k = 0; k < 10; ++k)
    if (auto pose = meshes3::read_off((folder / ("cat-" + std::to_string(k) + ".off")).string()))
      poses.push_back(std::move(*pose));
  return poses;
}

/// The most triangles inverted (frame_metrics3.hpp: a triangle whose normal opposes the one its local map A_i(t)
/// expects) in the 11 frames t = 0, 0.1, …, 1 of `engine`, and the most of them away from the target's folds
/// (neither a fold nor sharing a vertex with one: target_folds3.hpp).
struct Inverted {
  Eigen::Index all = 0, away_from_folds = 0;
};
Inverted most_inverted(const Mesh3& source, const Mesh3& target, const Interpolation3& engine) {
  const std::vector<unsigned char> near = near_folds(source, target_folds(source, target));
  Inverted most;
  for (int f = 0; f <= 10; ++f) {
    const FrameMetrics3 m = frame_metrics3(source, engine.vertices_at(f / 10.0), engine.local_maps_at(f / 10.0), near);
    most.all = std::max(most.all, m.inverted_elements);
    most.away_from_folds = std::max(most.away_from_folds, m.inverted_elements - m.inverted_near_folds);
  }
  return most;
}

// Continuity: the largest jump, max over vertices and consecutive frames of |v_k(t_{j+1}) − v_k(t_j)|, over the box
// diagonal; a snap of the tail would move it by about the tail's length, a tenth of the box or more, while a smooth
// motion over 20 steps moves a vertex by about its whole path / 20 (up to 0.048 measured, either branch: the
// frames are continuous in t for any fixed branches, so this bound does not tell the branches apart).
// Inversions: E^F does fold a few triangles of these pairs in mid-frames (exp-log's own maps never invert:
// local3_test). The poses themselves fold triangles within the surface against cat-0 (target_folds3.hpp: 9 in cat-5
// to 156 in cat-4), which the local maps turn by a half-turn about an axis in the surface. Measured in these 11
// frames, with the rotations turned along their carrier (rotation_carrier3.hpp): at most 11 of 14,410 inverted with
// the consistent branch (cat-4 and cat-7; 18 on cat-4 without the carrier); the principal branch folds 207 on cat-4
// and 107 on cat-7, the poses whose tail turns. Away from the target's folds (neither a fold nor sharing a vertex
// with one): none but 1 on cat-7 (before the carrier's fill and the walk's prediction 1 on cat-7, 4 on cat-8 and 2
// on cat-9). The check asks for at most 0.2% (29 triangles) on every pose, at most 3 away from the folds, and, on
// the two tail poses, at most a third of the principal branch's count.
TEST(Cat3, ExpLogFramesAreContinuousAndFoldFewTriangles) {
  const std::vector<Mesh3> poses = cat_poses();
  if (poses.size() < 10) GTEST_SKIP() << "the cat poses (../shared/data/meshes3d/cat/cat-*.off) are not present";
  const double box = meshes3::box_diagonal(poses[0].vertices);
  Interpolation3Options principal;
  principal.rotation_branch = affinterp::global::RotationBranch::principal;
  double worst_jump = 0;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const Interpolation3 engine(poses[0], poses[k]);
    std::vector<double> times;
    for (int f = 0; f <= 20; ++f) times.push_back(f / 20.0);
    const std::vector<Eigen::Matrix3Xd> frames = engine.vertices_at(times);
    EXPECT_LT((frames.front() - poses[0].vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    EXPECT_LT((frames.back() - poses[k].vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    double jump = 0;
    for (std::size_t f = 1; f < frames.size(); ++f)
      jump = std::max(jump, (frames[f] - frames[f - 1]).colwise().norm().maxCoeff() / box);
    const Inverted most = most_inverted(poses[0], poses[k], engine);
    const Eigen::Index inverted = most.all;
    std::cout << "cat-0 -> cat-" << k << ": largest jump between 21 frames " << jump
              << " of the box; most inverted triangles in 11 frames " << inverted << ", away from the "
              << target_folds(poses[0], poses[k]).size() << " target folds " << most.away_from_folds << "\n";
    EXPECT_LE(inverted, 29) << "cat-" << k;
    EXPECT_LE(most.away_from_folds, 3) << "cat-" << k;
    if (k == 4 || k == 7) {
      const Eigen::Index inverted_principal =
          most_inverted(poses[0], poses[k], Interpolation3(poses[0], poses[k], principal)).all;
      std::cout << "  principal branch: " << inverted_principal << "\n";
      EXPECT_LE(3 * inverted, inverted_principal) << "cat-" << k;
    }
    worst_jump = std::max(worst_jump, jump);
  }
  EXPECT_LT(worst_jump, 0.06);
}

}  // namespace cat3_test
