// The global chapter's figures: beside each filmstrip and metric chart, a viewer page of the same
// interpolations with their energies, listed last among the figures so that the report links it.
#include "experiments/claims/global/animation.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace affinterp::claims::global_figures::global_animation_test {
namespace {

namespace fs = std::filesystem;

TEST(GlobalFigures, DrawAViewerBesideEachAnimation) {
  const auto pair = shapes::make_shape("man-wave");
  global::InterpolationOptions options;
  options.energy = global::Energy::F;
  options.constraints.barycentre = global::BarycentreLocus{};
  const Animation animation = animate("E^F", pair.source, global::Interpolation(pair.source, pair.target, options), 5);
  ASSERT_EQ(animation.energy.size(), 5u);
  EXPECT_LT(animation.energy.front(), 1e-12) << "t = 0 is the source";
  EXPECT_GT(animation.energy[2], 0.0);

  RunSettings settings;
  settings.figure_dir = fs::temp_directory_path() / "affinterp_global_animation_test";
  fs::remove_all(settings.figure_dir);
  fs::create_directories(settings.figure_dir);
  const auto refs = draw_animations(settings, "test-man", pair.source, {animation}, {0, 2, 4}, "test");
  ASSERT_FALSE(refs.empty());
  EXPECT_EQ(refs.back(), "figures/test-man-viewer.html");
  std::ifstream in(settings.figure_dir / "test-man-viewer.html");
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_NE(page.str().find("{\"name\":\"E_t\""), std::string::npos) << "the energy over time";
  fs::remove_all(settings.figure_dir);
}

}  // namespace
}  // namespace affinterp::claims::global_figures::global_animation_test
