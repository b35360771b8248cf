// The 3D frames-against-baselines record (engine3_quality.hpp) on a generated tube turned by 1.4π: every method
// has a row, E^F with the linear homotopy is the per-vertex linear blend, exp-log on consistent branches inverts no
// triangle where the linear blend collapses the tube through its axis; written to claims.json, read back
// unchanged and rendered into the report's 3D table.
#include "experiments/measurements/engine3_quality.hpp"
#include "experiments/inputs/shapes3d/bar3.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

namespace affinterp::measurements::engine3_quality_test {
namespace {

std::size_t row(const Engine3Quality& quality, const std::string& method) {
  for (std::size_t m = 0; m < quality.methods.size(); ++m)
    if (quality.methods[m] == method) return m;
  ADD_FAILURE() << "no row " << method;
  return 0;
}

TEST(Engine3Quality, LinearBlendFoldsATurnedTubeWhereExpLogDoesNot) {
  const global3::Mesh3 tube = shapes3d::triangle_tube(12, 12, 4);
  const PosePair pair{"tube → twisted", tube, shapes3d::twisted(tube, 1.4 * std::numbers::pi, 4)};
  const Engine3Quality quality = engine3_quality({pair}, 5);
  ASSERT_EQ(quality.methods.size(), 9u);
  ASSERT_EQ(quality.pairs, std::vector<std::string>{"tube → twisted"});
  const auto& linear_blend = quality.cells[row(quality, "per-vertex linear blend")][0];
  const auto& ef_linear = quality.cells[row(quality, "E^F, linear")][0];
  const auto& exp_log = quality.cells[row(quality, "E^F, exp-log")][0];
  EXPECT_GT(linear_blend.most_inverted, 0);
  EXPECT_EQ(ef_linear.most_inverted, linear_blend.most_inverted);
  EXPECT_NEAR(ef_linear.middle_distortion, linear_blend.middle_distortion, 1e-6 * linear_blend.middle_distortion);
  EXPECT_EQ(exp_log.most_inverted, 0);
  EXPECT_EQ(quality.target_folds, std::vector<long>{0});  // a twist folds no triangle within the surface
  EXPECT_EQ(linear_blend.most_inverted_away, linear_blend.most_inverted);
  EXPECT_GT(exp_log.middle_distortion, 1);
  // a free twist: nothing for the elements' own turns to undo, so the refined frames invert none either
  EXPECT_EQ(quality.cells[row(quality, "exp-log, 5 as-rigid-as-possible steps")][0].most_inverted, 0);
  EXPECT_FALSE(quality.closeup) << "exp-log inverts nothing to show up close";

  const nlohmann::json written = quality;
  EXPECT_EQ(nlohmann::json(written.get<Engine3Quality>()), written);
  nlohmann::json doc = {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}};
  doc["engine3_quality"] = written;
  const std::string md = report::render(doc).summary;
  EXPECT_NE(md.find("### 3D frames against baselines"), std::string::npos) << md;
  EXPECT_NE(md.find("| E^F, exp-log | 0, "), std::string::npos) << md;
  EXPECT_NE(md.find("| target's folds (the input) | 0 | 0 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Up close"), std::string::npos) << md;
}

}  // namespace
}  // namespace affinterp::measurements::engine3_quality_test
