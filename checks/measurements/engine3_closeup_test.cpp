// The close-up of a frame's inversions (engine3_closeup.hpp) on a generated tube whose frame has one vertex dragged
// past the next ring, which turns the triangles around it over within the surface: the piece is centred on one of
// them, holds the vertex rings around it, marks exactly the inverted triangles it holds, and takes its vertices
// from the source, the frame and the target; none for a frame that inverts nothing or for tetrahedra; written to
// claims.json and read back unchanged, and described in the report with its figure.
#include "experiments/measurements/engine3_closeup.hpp"
#include "experiments/inputs/shapes3d/bar3.hpp"
#include "experiments/measurements/engine3_quality.hpp"
#include "reports/generator/report.hpp"
#include "theory/global3/frame_metrics3.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

namespace affinterp::measurements::engine3_closeup_test {
namespace {

using plots::FaceMark;

constexpr int rings = 12, around = 12;
constexpr double length = 4;

struct Dragged {
  global3::Mesh3 tube = shapes3d::triangle_tube(rings, around, length);
  global3::Mesh3 target = shapes3d::twisted(tube, 0.5, length);
  Eigen::Matrix3Xd frame = tube.vertices;
  Dragged() { frame(0, 5 * around + 3) += 1.5 * length / rings; }  // past the next ring
};

TEST(Engine3Closeup, CentresOnAnInvertedTriangleAndMarksTheInvertedOnes) {
  const Dragged d;
  const std::vector<Eigen::Index> inverted = global3::frame_metrics3(d.tube, d.frame).inverted;
  ASSERT_FALSE(inverted.empty());
  const auto closeup = closeup_of_frame("tube", d.tube, d.target, 0.5, d.frame, {}, 2);
  ASSERT_TRUE(closeup);
  EXPECT_EQ(closeup->centre, inverted.front());  // the twist folds nothing: every inverted triangle is away
  EXPECT_EQ(closeup->inverted, static_cast<long>(inverted.size()));
  EXPECT_EQ(closeup->inverted_away, closeup->inverted);
  // two vertex rings around one triangle of a regular tube: more than its star, less than the tube
  EXPECT_GT(closeup->triangles.cols(), 12);
  EXPECT_LT(closeup->triangles.cols(), d.tube.element_count() / 2);
  const auto n = static_cast<std::size_t>(closeup->triangles.cols());
  ASSERT_EQ(closeup->frame_marks.size(), n);
  ASSERT_EQ(closeup->fold_marks.size(), n);
  EXPECT_EQ(static_cast<long>(std::count(closeup->frame_marks.begin(), closeup->frame_marks.end(), FaceMark::inverted)),
            closeup->inverted);  // the dragged vertex's triangles all lie within the piece
  EXPECT_EQ(std::count(closeup->fold_marks.begin(), closeup->fold_marks.end(), FaceMark::none), static_cast<long>(n));
  // each panel's vertices are the same mesh vertices: the frame moved one of them, the target twisted all
  const Eigen::Index moved = ((closeup->frame - closeup->source).colwise().norm().array() > 0).count();
  EXPECT_EQ(moved, 1);
  EXPECT_EQ(closeup->target.cols(), closeup->source.cols());
  EXPECT_NEAR((closeup->target - closeup->source).row(0).norm(), 0, 1e-15);  // a twist about x keeps x
}

TEST(Engine3Closeup, NoneWhereNothingIsInvertedOrForTetrahedra) {
  const Dragged d;
  EXPECT_FALSE(closeup_of_frame("tube", d.tube, d.target, 0.5, d.tube.vertices, {}));
  const global3::Mesh3 bar = shapes3d::tetrahedral_bar(4, 4);
  Eigen::Matrix3Xd mirrored = bar.vertices;
  mirrored.row(2) *= -1;  // every tetrahedron inverted
  EXPECT_FALSE(closeup_of_frame("bar", bar, bar, 0.5, mirrored, {}));
}

TEST(Engine3Closeup, IsReadBackUnchangedAndDescribedInTheReport) {
  const Dragged d;
  Engine3Quality quality;
  quality.frames = 3;
  quality.pairs = {"tube"}, quality.elements = {d.tube.element_count()}, quality.target_folds = {0};
  quality.closeup = closeup_of_frame("tube", d.tube, d.target, 0.5, d.frame, {});
  ASSERT_TRUE(quality.closeup);
  quality.figures = {"figures/sequel-3d-inversion-closeup.png"};
  const nlohmann::json written = quality;
  EXPECT_EQ(nlohmann::json(written.get<Engine3Quality>()), written);
  nlohmann::json doc = {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}};
  doc["engine3_quality"] = written;
  const std::string md = report::render(doc).summary;
  EXPECT_NE(md.find("Up close, E^F exp-log's frame with the most inverted triangles away from its target's folds: "
                    "tube at t = 0.50, " +
                    std::to_string(quality.closeup->inverted) + " inverted"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("![inverted triangles up close](figures/sequel-3d-inversion-closeup.png)"), std::string::npos);
}

}  // namespace
}  // namespace affinterp::measurements::engine3_closeup_test
