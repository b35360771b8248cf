#include "plots/mesh_animation.hpp"

#include "plots/cairo_page.hpp"
#include "plots/gif_writer.hpp"
#include "plots/mesh_painter.hpp"

#include <cairo.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace affinterp::plots {

namespace {

const MeshColours colours{{0.839, 0.902, 0.961}, {0.173, 0.365, 0.541}};

/// The colours the frames are drawn with and, for antialiased edges and text, 18 steps between each two.
std::vector<Colour> palette() {
  const std::vector<Colour> keys{{1, 1, 1}, colours.fill, colours.edge, colours.flipped, {0, 0, 0}};
  std::vector<Colour> result = keys;
  for (std::size_t a = 0; a < keys.size(); ++a)
    for (std::size_t b = a + 1; b < keys.size(); ++b)
      for (int s = 1; s < 19; ++s) result.push_back(mix(keys[a], keys[b], s / 19.0));
  return result;
}

}  // namespace

void write_animation_gif(const std::filesystem::path& gif, const Eigen::Matrix3Xi& triangles,
                         const std::vector<MeshFrame>& frames, int delay_cs) {
  if (frames.empty()) throw std::invalid_argument("write_animation_gif: no frames");
  Eigen::Vector2d lo = frames.front().vertices.rowwise().minCoeff(), hi = frames.front().vertices.rowwise().maxCoeff();
  for (const MeshFrame& frame : frames) {
    lo = lo.cwiseMin(frame.vertices.rowwise().minCoeff());
    hi = hi.cwiseMax(frame.vertices.rowwise().maxCoeff());
  }
  const Eigen::Vector2d margin = 0.05 * (hi - lo).cwiseMax(1e-9);
  lo -= margin, hi += margin;
  const int width = 480, height = std::clamp(static_cast<int>(width * (hi.y() - lo.y()) / (hi.x() - lo.x())), 120, 960);
  const View view = centred(lo, hi, fitting_scale(lo, hi, width, height), width / 2.0, height / 2.0);

  const MeshPainter painter(triangles);
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  GifWriter writer(gif, width, height, palette(), delay_cs);
  for (const MeshFrame& frame : frames) {
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    painter.paint(cr.get(), frame.vertices, view, colours);
    left_text(cr.get(), frame.label, 8, 18, 13);
    cairo_surface_flush(surface.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot draw " + gif.string() + ": " + cairo_status_to_string(cairo_status(cr.get())));
    writer.add_frame(cairo_image_surface_get_data(surface.get()), cairo_image_surface_get_stride(surface.get()));
  }
  writer.finish();
}

}  // namespace affinterp::plots
