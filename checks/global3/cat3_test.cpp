// The 3D engine on real data: the cat poses of Sumner and Popović ("Deformation transfer for triangle meshes",
// SIGGRAPH 2004), ten poses of one triangle mesh (7,207 vertices, 14,410 triangles), in ../shared/data when
// present (skipped otherwise). Exp-log from cat-0 to each other pose: frames continuous at 21 frames (the tail,
// turned by up to 180° in some poses, among them), and the ends the poses.
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

// Continuity: the largest jump, max over vertices and consecutive frames of |v_k(t_{j+1}) − v_k(t_j)|, over the box
// diagonal; a snap of the tail (a branch flip) would move it by about the tail's length, a tenth of the box or
// more, while a smooth motion over 20 steps moves a vertex by about its whole path / 20 (up to 0.048 measured).
// Inversions (frame_metrics3.hpp: a triangle whose normal opposes the one its local map A_i(t) expects) are
// measured and printed, not asserted: E^F does fold some triangles of these pairs in mid-frames (exp-log's own
// maps never invert: local3_test). The poses themselves hold creases against cat-0: between 44 (cat-6) and 387
// (cat-4) pairs of adjacent triangles whose maps from cat-0 differ by more than a quarter turn, none of them a
// sliver, where no frame can follow both neighbours' local maps; the counts are a finding for the report.
TEST(Cat3, ExpLogFramesAreContinuousAndEndAtThePoses) {
  const std::vector<Mesh3> poses = cat_poses();
  if (poses.size() < 10) GTEST_SKIP() << "the cat poses (../shared/data/meshes3d/cat/cat-*.off) are not present";
  const double box = meshes3::box_diagonal(poses[0].vertices);
  double worst_jump = 0;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const Interpolation3 engine(poses[0], poses[k]);
    std::vector<double> times;
    for (int f = 0; f <= 20; ++f) times.push_back(f / 20.0);
    const std::vector<Eigen::Matrix3Xd> frames = engine.vertices_at(times);
    EXPECT_LT((frames.front() - poses[0].vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    EXPECT_LT((frames.back() - poses[k].vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    double jump = 0;
    Eigen::Index inverted = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
      if (f > 0) jump = std::max(jump, (frames[f] - frames[f - 1]).colwise().norm().maxCoeff() / box);
      if (f % 2 == 0)  // the 11 frames t = 0, 0.1, …, 1
        inverted =
            std::max(inverted, frame_metrics3(poses[0], frames[f], engine.local_maps_at(times[f])).inverted_elements);
    }
    std::cout << "cat-0 -> cat-" << k << ": largest jump between 21 frames " << jump
              << " of the box; most inverted triangles in 11 frames " << inverted << "\n";
    worst_jump = std::max(worst_jump, jump);
  }
  EXPECT_LT(worst_jump, 0.06);
}

}  // namespace cat3_test
