// The 3D engine on real data: the cat poses of Sumner and Popović ("Deformation transfer for triangle meshes",
// SIGGRAPH 2004), ten poses of one triangle mesh (7,207 vertices, 14,410 triangles), in ../shared/data when
// present (skipped otherwise). Exp-log from cat-0 to each other pose: frames continuous at 21 frames (the tail,
// turned by up to 180° in some poses, among them), the ends the poses, few folded triangles.
#include "checks/global3/meshes3.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/interpolation3.hpp"

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
/// expects) in the 11 frames t = 0, 0.1, …, 1 of `engine`.
Eigen::Index most_inverted(const Mesh3& source, const Interpolation3& engine) {
  Eigen::Index inverted = 0;
  for (int f = 0; f <= 10; ++f)
    inverted = std::max(
        inverted,
        frame_metrics3(source, engine.vertices_at(f / 10.0), engine.local_maps_at(f / 10.0)).inverted_elements);
  return inverted;
}

// Continuity: the largest jump, max over vertices and consecutive frames of |v_k(t_{j+1}) − v_k(t_j)|, over the box
// diagonal; a snap of the tail would move it by about the tail's length, a tenth of the box or more, while a smooth
// motion over 20 steps moves a vertex by about its whole path / 20 (up to 0.048 measured, either branch: the
// frames are continuous in t for any fixed branches, so this bound does not tell the branches apart).
// Inversions: E^F does fold a few triangles of these pairs in mid-frames (exp-log's own maps never invert:
// local3_test). The poses themselves hold creases against cat-0: between 44 (cat-6) and 387 (cat-4) pairs of
// adjacent triangles whose maps from cat-0 differ by more than a quarter turn, none of them a sliver, where no frame
// can follow both neighbours' local maps. Measured: at most 18 of 14,410 with the consistent branch (cat-4); the
// principal branch folds 207 on cat-4 and 107 on cat-7, the poses whose tail turns, and 0 to 23 on the others
// (the consistent branch one more on cat-1 and cat-6, fewer on cat-3, cat-5, cat-8, cat-9). The check asks for at most
// 0.2% (29 triangles) on every pose and, on the two tail poses, at most a third of the principal branch's count.
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
    const Eigen::Index inverted = most_inverted(poses[0], engine);
    std::cout << "cat-0 -> cat-" << k << ": largest jump between 21 frames " << jump
              << " of the box; most inverted triangles in 11 frames " << inverted << "\n";
    EXPECT_LE(inverted, 29) << "cat-" << k;
    if (k == 4 || k == 7) {
      const Eigen::Index inverted_principal = most_inverted(poses[0], Interpolation3(poses[0], poses[k], principal));
      std::cout << "  principal branch: " << inverted_principal << "\n";
      EXPECT_LE(3 * inverted, inverted_principal) << "cat-" << k;
    }
    worst_jump = std::max(worst_jump, jump);
  }
  EXPECT_LT(worst_jump, 0.06);
}

}  // namespace cat3_test
