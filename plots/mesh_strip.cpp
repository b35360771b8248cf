#include "plots/mesh_strip.hpp"

#include "plots/cairo_page.hpp"
#include "plots/mesh_painter.hpp"

#include <algorithm>
#include <stdexcept>

namespace affinterp::plots {

namespace {

/// The first frame's colours and the last's; frames between are mixed in proportion to their place.
const MeshColours earliest{{0.863, 0.914, 0.961}, {0.490, 0.624, 0.761}};
const MeshColours latest{{0.561, 0.694, 0.831}, {0.122, 0.247, 0.400}};

}  // namespace

std::vector<std::string> draw_filmstrip(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                        const std::vector<MeshFrame>& frames, const std::string& title) {
  if (frames.empty()) throw std::invalid_argument("draw_filmstrip: no frames");
  double width = 0, height = 0;
  for (const MeshFrame& frame : frames) {
    const Eigen::Vector2d extent = frame.vertices.rowwise().maxCoeff() - frame.vertices.rowwise().minCoeff();
    width = std::max(width, extent.x());
    height = std::max(height, extent.y());
  }
  width = std::max(width, 1e-9), height = std::max(height, 1e-9);
  const double n = static_cast<double>(frames.size());
  const int pixel_width = std::clamp(static_cast<int>(220 * frames.size()), 400, 2400);
  const double cell = pixel_width / n;                                  // each frame centred in a cell
  const double scale = std::min(cell / (1.15 * width), 1000 / height);  // a common scale
  const double top = title.empty() ? 8 : 36, drawing_height = scale * height, label_size = 12;
  const int pixel_height = static_cast<int>(top + drawing_height + 12 + 2 * label_size);

  const MeshPainter painter(triangles);
  return render_png_and_svg(stem, pixel_width, pixel_height, [&](cairo_t* cr) {
    if (!title.empty()) centred_text(cr, title, pixel_width / 2.0, 24, 14);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const Eigen::Matrix2Xd& v = frames[f].vertices;
      const double centre = cell * (static_cast<double>(f) + 0.5);
      const View view =
          centred(v.rowwise().minCoeff(), v.rowwise().maxCoeff(), scale, centre, top + drawing_height / 2);
      const double s = frames.size() > 1 ? static_cast<double>(f) / (n - 1) : 1.0;
      const MeshColours colours{mix(earliest.fill, latest.fill, s), mix(earliest.edge, latest.edge, s)};
      painter.paint(cr, v, view, colours);
      centred_text(cr, frames[f].label, centre, top + drawing_height + 12 + label_size, label_size);
    }
  });
}

}  // namespace affinterp::plots
