// The 3D engine's input rules (theory/global3/mesh3_validation.hpp): each bad input refused with one line, and
// the metrics of frames (frame_metrics3.hpp).
#include "theory/global3/mesh3_validation.hpp"
#include "checks/global3/meshes3.hpp"
#include "theory/global3/blend3.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/interpolation3.hpp"

#include <gtest/gtest.h>

namespace mesh3_validation_test {

using namespace affinterp::global3;
using affinterp::global::InvalidMesh;

/// The message of the InvalidMesh the pair (source, target) is refused with, or "" if it is accepted.
std::string refusal(const Mesh3& source, const Mesh3& target) {
  try {
    Interpolation3 engine(source, target);
  } catch (const InvalidMesh& error) {
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    return error.what();
  }
  return "";
}

TEST(Mesh3Validation, AcceptsValidPairs) {
  const Mesh3 bar = meshes3::tetrahedral_bar(3, 2), tube = meshes3::triangle_tube(3, 6, 2);
  EXPECT_EQ(refusal(bar, meshes3::bent(bar, 2)), "");
  EXPECT_EQ(refusal(tube, meshes3::bent(tube, 2)), "");
}

TEST(Mesh3Validation, RefusesEachBadInputWithOneLine) {
  const Mesh3 bar = meshes3::tetrahedral_bar(3, 2), tube = meshes3::triangle_tube(3, 6, 2);
  Mesh3 other = bar;
  std::swap(other.elements(0, 4), other.elements(1, 4));
  EXPECT_NE(refusal(bar, other).find("connectivity"), std::string::npos);
  EXPECT_NE(refusal(bar, tube).find("connectivity"), std::string::npos);
  Mesh3 flat = bar;  // vertex 4's slice collapsed onto slice 0: the tetrahedra between them are flat
  flat.vertices.col(4) = bar.vertices.col(0);
  EXPECT_NE(refusal(bar, flat).find("degenerate"), std::string::npos) << refusal(bar, flat);
  Mesh3 flat_triangle = tube;
  flat_triangle.vertices.col(flat_triangle.elements(2, 0)) = flat_triangle.vertices.col(flat_triangle.elements(0, 0));
  EXPECT_NE(refusal(tube, flat_triangle).find("degenerate"), std::string::npos) << refusal(tube, flat_triangle);
  Mesh3 mirrored = bar;
  mirrored.vertices.row(2) = -mirrored.vertices.row(2);
  EXPECT_NE(refusal(bar, mirrored).find("inverted"), std::string::npos);
  Mesh3 nan = bar;
  nan.vertices(1, 3) = NAN;
  EXPECT_NE(refusal(bar, nan).find("not finite"), std::string::npos);
  EXPECT_NE(refusal(nan, bar).find("not finite"), std::string::npos);
  Mesh3 out_of_range = bar;
  out_of_range.elements(2, 1) = 1000;
  EXPECT_NE(refusal(out_of_range, out_of_range).find("out of range"), std::string::npos);
  Mesh3 repeated = bar;
  repeated.elements(2, 1) = repeated.elements(0, 1);
  EXPECT_NE(refusal(repeated, repeated).find("repeats"), std::string::npos);
  Mesh3 five_rows{bar.vertices, Eigen::MatrixXi::Zero(5, 2)};
  EXPECT_NE(refusal(five_rows, five_rows).find("3 (triangles) or 4"), std::string::npos);
}

TEST(Mesh3Validation, RefusesDisconnectedMeshes) {
  const Mesh3 tube = meshes3::triangle_tube(2, 5, 2);
  Mesh3 two{Eigen::Matrix3Xd(3, 2 * tube.vertex_count()), Eigen::MatrixXi(3, 2 * tube.element_count())};
  two.vertices << tube.vertices, (tube.vertices.colwise() + Eigen::Vector3d(10, 0, 0));
  two.elements << tube.elements, (tube.elements.array() + static_cast<int>(tube.vertex_count())).matrix();
  EXPECT_NE(refusal(two, two).find("not connected"), std::string::npos);
  Mesh3 lonely = tube;
  lonely.vertices.conservativeResize(3, tube.vertex_count() + 1);
  lonely.vertices.col(tube.vertex_count()).setZero();
  EXPECT_NE(refusal(lonely, lonely).find("in no element"), std::string::npos);
}

TEST(FrameMetrics3, RestFrameIsUndistortedAndAMirroredOneInverted) {
  const Mesh3 bar = meshes3::tetrahedral_bar(3, 2), tube = meshes3::triangle_tube(3, 6, 2);
  for (const Mesh3& mesh : {bar, tube}) {
    const FrameMetrics3 rest = frame_metrics3(mesh, mesh.vertices);
    EXPECT_EQ(rest.inverted_elements, 0);
    EXPECT_NEAR(rest.min_ratio, 1, 1e-14);
    EXPECT_NEAR(rest.max_distortion, 1, 1e-12);
    EXPECT_NEAR(rest.measure_ratio, 1, 1e-14);
  }
  Eigen::Matrix3Xd mirrored = bar.vertices;
  mirrored.row(2) *= -1;
  EXPECT_EQ(frame_metrics3(bar, mirrored).inverted_elements, bar.element_count());
  // A surface triangle is inverted against the normal its local map expects: here a half turn about x, which
  // the unmoved tube's every normal opposes.
  const std::vector<Eigen::Matrix3d> half_turn(static_cast<std::size_t>(tube.element_count()),
                                               Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix());
  EXPECT_EQ(frame_metrics3(tube, tube.vertices, half_turn).inverted_elements, tube.element_count());
  Eigen::Matrix3Xd stretched = bar.vertices;
  stretched.row(0) *= 2;
  const FrameMetrics3 metrics = frame_metrics3(bar, stretched);
  EXPECT_NEAR(metrics.min_ratio, 2, 1e-13);
  EXPECT_NEAR(metrics.max_distortion, 2, 1e-12);
  EXPECT_NEAR(metrics.measure_ratio, 2, 1e-13);
}

}  // namespace mesh3_validation_test
