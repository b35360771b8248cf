// plots::draw_patches3: a marked triangle is drawn over the unmarked ones, so that a mark behind the surface still
// shows; read back from the PNG written.
#include "plots/mesh3/mesh3_figures.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace affinterp::plots {
namespace {

namespace fs = std::filesystem;

/// Pixels of the PNG that are clearly red (the inverted mark's colour, shaded or not).
int red_pixels(const fs::path& png) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
  EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(image), height = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  int red = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto* p = reinterpret_cast<const std::uint32_t*>(data + y * stride) + x;  // ARGB, native order
      const int r = (*p >> 16) & 0xff, g = (*p >> 8) & 0xff, b = *p & 0xff;
      red += r > 100 && r > 2 * g && r > 2 * b;
    }
  cairo_surface_destroy(image);
  return red;
}

TEST(Patches3, AMarkedTriangleShowsThroughTheSurfaceInFrontOfIt) {
  // Two squares of two triangles each, a unit square a unit behind one twice its side along their common normal:
  // turned to face the viewer, the front one hides the back one with a margin.
  Eigen::Matrix3Xd vertices(3, 8);
  vertices << -0.5, 1.5, 1.5, -0.5, 0, 1, 1, 0,  //
      -0.5, -0.5, 1.5, 1.5, 0, 0, 1, 1,          //
      0, 0, 0, 0, -1, -1, -1, -1;
  Eigen::Matrix3Xi triangles(3, 4);
  triangles << 0, 0, 4, 4,  //
      1, 2, 5, 6,           //
      2, 3, 6, 7;
  const fs::path folder = fs::temp_directory_path() / "affinterp_patches3_test";
  fs::create_directories(folder);
  std::vector<FaceMark> marks(4, FaceMark::none);
  marks[3] = FaceMark::inverted;  // behind
  const auto unmarked = draw_patches3(folder / "unmarked", triangles, {{vertices, {}, "plain"}}, {}, "plain");
  const auto marked = draw_patches3(folder / "marked", triangles, {{vertices, marks, "marked"}},
                                    {{FaceMark::fold, "a fold"}}, "one mark behind");
  ASSERT_EQ(marked.size(), 2u);
  EXPECT_EQ(red_pixels(folder / "unmarked.png"), 0);
  EXPECT_GT(red_pixels(folder / "marked.png"), 100);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace affinterp::plots
