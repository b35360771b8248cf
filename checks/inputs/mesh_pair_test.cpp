// Checking a source/target pair (theory/global/mesh_validation via io::check_mesh_pair): each kind of
// invalid pair gives one line naming the file and the element.
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "theory/global/mesh_validation.hpp"

#include "checks/global/strip.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace mesh_pair_test {

namespace {

using namespace affinterp;

using affinterp::global::testing::unit_square;

std::string pair_error(global::Mesh source, global::Mesh target, bool allow_flipped = false) {
  try {
    io::check_mesh_pair(std::move(source), std::move(target), "s.obj", "t.obj", {allow_flipped});
  } catch (const io::MeshFileError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshPair, AcceptsACompatiblePair) {
  global::Mesh target = unit_square();
  target.vertices *= 2;
  const io::MeshPair pair = io::check_mesh_pair(unit_square(), target, "s", "t");
  EXPECT_FALSE(pair.reoriented);
  EXPECT_TRUE(pair.flipped_target_triangles.empty());
}

TEST(MeshPair, RefusesIncompatibleOrMalformedMeshesNamingTheElement) {
  global::Mesh fewer = unit_square();
  fewer.vertices.conservativeResize(2, 3);
  fewer.triangles.conservativeResize(3, 1);
  EXPECT_EQ(pair_error(unit_square(), fewer), "t.obj: the target has 3 vertices, the source 4");
  global::Mesh other = unit_square();
  other.triangles(2, 1) = 1;
  EXPECT_EQ(pair_error(unit_square(), other),
            "t.obj: triangle 1 differs between source and target: the face lists must match");
  global::Mesh out_of_range = unit_square();
  out_of_range.triangles(1, 0) = 7;
  EXPECT_EQ(pair_error(out_of_range, unit_square()), "s.obj: triangle 0 refers to vertex 7 of 4");
  global::Mesh repeated = unit_square();
  repeated.triangles(1, 0) = 0;
  EXPECT_EQ(pair_error(repeated, unit_square()), "s.obj: triangle 0 uses a vertex twice");
  global::Mesh nan = unit_square();
  nan.vertices(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(pair_error(unit_square(), nan), "t.obj: vertex 2 has a non-finite coordinate");
  EXPECT_EQ(pair_error(global::Mesh{}, unit_square()), "s.obj: the mesh has no vertices");
  global::Mesh no_triangles = unit_square();
  no_triangles.triangles.resize(3, 0);
  EXPECT_EQ(pair_error(no_triangles, no_triangles), "s.obj: the mesh has no triangles");
}

TEST(MeshPair, RefusesZeroAreaAndFoldedSources) {
  global::Mesh flat = unit_square();
  flat.vertices.col(2) = Eigen::Vector2d(0.5, 0);  // triangle 0 = (0,0), (1,0), (0.5,0)
  EXPECT_EQ(pair_error(flat, flat), "s.obj: source triangle 0 has zero area");
  global::Mesh folded = unit_square();
  folded.vertices.col(3) = Eigen::Vector2d(2, -1);  // triangle 1 turns clockwise
  EXPECT_EQ(pair_error(folded, folded),
            "s.obj: source triangles 0 (counter-clockwise) and 1 (clockwise) have opposite orientations: the source "
            "folds over itself");
}

TEST(MeshPair, ReorientsAClockwiseSourceAndItsTarget) {
  global::Mesh clockwise = unit_square();
  global::reverse_orientation(clockwise);
  global::Mesh target = clockwise;
  target.vertices *= 3;
  const io::MeshPair pair = io::check_mesh_pair(clockwise, target, "s", "t");
  EXPECT_TRUE(pair.reoriented);
  EXPECT_EQ(pair.source.triangles, unit_square().triangles);
  EXPECT_EQ(pair.target.triangles, unit_square().triangles);
  EXPECT_GT(pair.source.doubled_signed_area(0), 0);
}

TEST(MeshPair, FlippedTargetTrianglesAreRefusedUnlessAllowed) {
  global::Mesh mirrored = unit_square();
  mirrored.vertices.row(0) *= -1;
  EXPECT_EQ(pair_error(unit_square(), mirrored),
            "t.obj: 2 target triangle(s) flipped or collapsed relative to the source, first triangle 0 (allow with "
            "--allow-flipped-target)");
  const io::MeshPair pair = io::check_mesh_pair(unit_square(), mirrored, "s", "t", {.allow_flipped_target = true});
  EXPECT_EQ(pair.flipped_target_triangles, (std::vector<Eigen::Index>{0, 1}));
}

}  // namespace

}  // namespace mesh_pair_test
