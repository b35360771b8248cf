// experiments/inputs/compatible_pair: the meshes from two outlines share one triangle list, have no flipped
// or degenerate triangle in either shape, keep the outlines as their first vertices, and are accepted by the
// interpolation; malformed pairs get one-line errors. Outlines: checks/inputs/outlines (hand-drawn).
#include "experiments/inputs/compatible_pair.hpp"
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/inputs/outline_file.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace affinterp::io::compatible_pair_test {
namespace {

const std::string outlines = std::string(AFFINTERP_SOURCE_DIR) + "/checks/inputs/outlines/";

Eigen::Matrix2Xd outline(const std::string& name) { return read_outline(outlines + name); }

/// The pair is valid: one triangle list, every triangle counter-clockwise with a positive area in both meshes.
void expect_valid(const CompatiblePair& pair, const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target) {
  ASSERT_EQ(pair.source.triangles, pair.target.triangles);
  for (Eigen::Index i = 0; i < pair.source.triangle_count(); ++i) {
    EXPECT_GT(pair.source.doubled_signed_area(i), 0) << "source triangle " << i;
    EXPECT_GT(pair.target.doubled_signed_area(i), 0) << "target triangle " << i;
  }
  // Every triangle has a positive smallest angle, so none is degenerate.
  EXPECT_GT(pair.source_min_angle, 0);
  EXPECT_GT(pair.target_min_angle, 0);
  // The outlines' vertices come first, unchanged (reordered only when the outlines ran clockwise).
  ASSERT_GE(pair.source.vertex_count(), source.cols());
  EXPECT_EQ(pair.source.vertices.leftCols(source.cols()), source);
  EXPECT_EQ(pair.target.vertices.leftCols(target.cols()), target);
  // The pair is an input the engine takes: the reader's checks and an interpolation at t = 1/2.
  const MeshPair checked = check_mesh_pair(pair.source, pair.target, "source", "target");
  EXPECT_TRUE(checked.flipped_target_triangles.empty());
  global::InterpolationOptions options;
  options.energy = global::Energy::F;
  options.constraints.pinned.push_back({0, 1.0});
  const global::Interpolation interpolation(checked.source, checked.target, options);
  EXPECT_TRUE(interpolation.vertices_at(0.5).allFinite());
}

struct OutlinePair {
  std::string source, target;
  int resample;  ///< 0: the outlines' own vertices
};

class CompatiblePairTest : public ::testing::TestWithParam<OutlinePair> {};

TEST_P(CompatiblePairTest, NoFlippedOrDegenerateTriangleInEither) {
  const OutlinePair& p = GetParam();
  Eigen::Matrix2Xd source = outline(p.source), target = outline(p.target);
  if (p.resample) source = resample_outline(source, p.resample), target = resample_outline(target, p.resample);
  const CompatiblePair pair = compatible_pair(source, target, p.source, p.target);
  expect_valid(pair, source, target);
  // Without the quality passes the construction alone is valid too.
  expect_valid(compatible_pair(source, target, p.source, p.target, 0), source, target);
}

INSTANTIATE_TEST_SUITE_P(
    HandDrawn, CompatiblePairTest,
    ::testing::Values(OutlinePair{"blob.txt", "rounded-square.txt", 0}, OutlinePair{"letter-c.txt", "star.txt", 0},
                      OutlinePair{"star.txt", "letter-c.txt", 0}, OutlinePair{"comb.txt", "letter-c.txt", 40},
                      OutlinePair{"comb.txt", "star.txt", 64}, OutlinePair{"blob.txt", "comb.txt", 30}));

TEST(CompatiblePair, OverlaysWhenNoTriangulationFitsBoth) {
  // Two darts: P's only diagonal is 0-2 (vertex 2 is reflex), Q's only one is 1-3, and each lies outside the
  // other shape; so the common refinement has the crossing of the two diagonals inside.
  Eigen::Matrix2Xd P(2, 4), Q(2, 4);
  P << 0, 2, 0.5, 0, 0, 0, 0.5, 2;
  Q << 2, 0.5, 0, 0, 0, 0.5, 2, 0;
  const CompatiblePair pair = compatible_pair(P, Q, "P", "Q", 0);
  EXPECT_GE(pair.steiner_vertices, 1);
  expect_valid(pair, P, Q);
  expect_valid(compatible_pair(P, Q, "P", "Q"), P, Q);
}

TEST(CompatiblePair, ClockwiseOutlinesKeepTheirNumbering) {
  const Eigen::Matrix2Xd source = outline("letter-c.txt").rowwise().reverse(),
                         target = outline("star.txt").rowwise().reverse();
  expect_valid(compatible_pair(source, target, "c", "star"), source, target);
}

std::string error_of(const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target) {
  try {
    compatible_pair(source, target, "S", "T");
  } catch (const OutlineError& e) {
    return e.what();
  }
  return "";
}

TEST(CompatiblePair, MalformedOutlinesGetOneLineErrors) {
  Eigen::Matrix2Xd square(2, 4), bowtie(2, 4), triangle(2, 3), spike(2, 4);
  square << 0, 1, 1, 0, 0, 0, 1, 1;
  bowtie << 0, 1, 0, 1, 0, 0, 1, 1;
  triangle << 0, 1, 0, 0, 0, 1;
  spike << 0, 2, 1, 0, 0, 0, 0, 1;  // edge 1-2 folds back over edge 0-1
  const auto expect_error = [](const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  expect_error(error_of(bowtie, square), "S: not a simple polygon: edges 1-2 and 3-0 meet");
  expect_error(error_of(square, spike), "T: not a simple polygon: edges 0-1 and 1-2 overlap");
  expect_error(error_of(square, triangle), "S has 4 vertices but T has 3");
  expect_error(error_of(square, square.rowwise().reverse()), "no orientation-preserving correspondence");
  Eigen::Matrix2Xd repeated = square;
  repeated.col(2) = repeated.col(0);
  expect_error(error_of(repeated, square), "vertices 0 and 2 coincide");
}

TEST(OutlineFile, TextAndSvgReadAlike) {
  const Eigen::Matrix2Xd text = parse_outline("# a square\n0 0\n1 0\n1 1\n0 1\n0 0\n", "t");
  const Eigen::Matrix2Xd polygon = parse_outline(R"(<svg><polygon points="0,0 1,0 1,-1 0,-1"/></svg>)", "p");
  const Eigen::Matrix2Xd path = parse_outline(R"(<svg><path d="M0 0 h1 v-1 L0 -1 z"/></svg>)", "q");
  EXPECT_EQ(text.cols(), 4);  // the closing repeat is dropped
  EXPECT_EQ(polygon, text);   // SVG's y points down
  EXPECT_EQ(path, text);
  EXPECT_THROW(parse_outline("0 0\n1 zero\n", "t"), MeshFileError);
  EXPECT_THROW(parse_outline(R"(<svg><path d="M0 0 C1 1 2 2 3 3 z"/></svg>)", "q"), MeshFileError);
}

TEST(ResampleOutline, EqualArcLengthFromVertexZero) {
  Eigen::Matrix2Xd square(2, 4);
  square << 0, 2, 2, 0, 0, 0, 2, 2;
  const Eigen::Matrix2Xd v = resample_outline(square, 8);
  Eigen::Matrix2Xd expected(2, 8);
  expected << 0, 1, 2, 2, 2, 1, 0, 0, 0, 0, 0, 1, 2, 2, 2, 1;
  EXPECT_TRUE(v.isApprox(expected, 1e-15)) << v;
}

}  // namespace
}  // namespace affinterp::io::compatible_pair_test
