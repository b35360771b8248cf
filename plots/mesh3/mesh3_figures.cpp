#include "plots/mesh3/mesh3_figures.hpp"

#include "plots/cairo_page.hpp"
#include "plots/mesh3/mesh3_render.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace affinterp::plots {

std::vector<std::string> draw_filmstrip3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                         const std::vector<Mesh3Frame>& frames, const std::string& title) {
  const Eigen::Matrix3Xi triangles = boundary_triangles(mesh);
  ProjectedBox box;
  for (const auto& frame : frames) box.include(frame.vertices);
  const double cell = 200, top = 30, bottom = 24;
  const int width = static_cast<int>(cell * static_cast<double>(frames.size()));
  return render_png_and_svg(stem, width, static_cast<int>(top + cell + bottom), [&](cairo_t* cr) {
    centred_text(cr, title, width / 2.0, 20, 14);
    const double last = std::max<double>(1, static_cast<double>(frames.size()) - 1);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const double x = cell * static_cast<double>(f);
      draw_mesh3(cr, triangles, frames[f].vertices, box, x, top, cell, static_cast<double>(f) / last);
      centred_text(cr, frames[f].label, x + cell / 2, top + cell + 16, 12);
    }
  });
}

std::vector<std::string> draw_blend_triangle3(const std::filesystem::path& stem, const global3::Mesh3& mesh,
                                              const std::vector<BlendThumbnail>& thumbnails,
                                              const std::vector<std::string>& pose_names, const std::string& title) {
  const Eigen::Matrix3Xi triangles = boundary_triangles(mesh);
  ProjectedBox box;
  for (const auto& thumb : thumbnails) box.include(thumb.vertices);
  const double cell = 150, side = 4 * cell, margin = 40;
  const double height_of_triangle = side * std::sqrt(3.0) / 2;
  // Corner k's page position (centre of its thumbnail): pose 0 at the top, 1 bottom left, 2 bottom right.
  const double left = margin + cell / 2, top = margin + cell / 2;
  const Eigen::Vector2d c0(left + side / 2, top), c1(left, top + height_of_triangle),
      c2(left + side, top + height_of_triangle);
  const int width = static_cast<int>(side + cell + 2 * margin);
  const int height = static_cast<int>(height_of_triangle + cell + 2 * margin);
  return render_png_and_svg(stem, width, height, [&](cairo_t* cr) {
    centred_text(cr, title, width / 2.0, 20, 14);
    for (const auto& thumb : thumbnails) {
      const Eigen::Vector2d at = thumb.weights[0] * c0 + thumb.weights[1] * c1 + thumb.weights[2] * c2;
      const double tint = thumb.weights[1] * 0.5 + thumb.weights[2];
      draw_mesh3(cr, triangles, thumb.vertices, box, at.x() - cell / 2 + margin / 2, at.y() - cell / 2, cell - margin,
                 tint);
    }
    const std::array<Eigen::Vector2d, 3> corners{c0, c1, c2};
    for (std::size_t k = 0; k < std::min<std::size_t>(3, pose_names.size()); ++k)
      centred_text(cr, pose_names[k], corners[k].x(), corners[k].y() + cell / 2 - 4, 12);
  });
}

}  // namespace affinterp::plots
