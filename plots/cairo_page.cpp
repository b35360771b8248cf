#include "plots/cairo_page.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <memory>
#include <stdexcept>

namespace affinterp::plots {

namespace fs = std::filesystem;

namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void check(cairo_status_t status, const fs::path& file) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write " + file.string() + ": " + cairo_status_to_string(status));
}

void paint_page(cairo_surface_t* surface, const std::function<void(cairo_t*)>& paint, const fs::path& file) {
  const Context cr(cairo_create(surface), cairo_destroy);
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());
  paint(cr.get());
  check(cairo_status(cr.get()), file);
}

void show_text(cairo_t* cr, const std::string& text, double x, double y, double size, double align) {
  cairo_save(cr);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, x - align * extents.x_advance, y);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

}  // namespace

std::vector<std::string> render_png_and_svg(const fs::path& stem, int width, int height,
                                            const std::function<void(cairo_t*)>& paint) {
  const fs::path png = stem.string() + ".png", svg = stem.string() + ".svg";
  {
    const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
    paint_page(surface.get(), paint, png);
    check(cairo_surface_write_to_png(surface.get(), png.c_str()), png);
  }
  {
    const Surface surface(cairo_svg_surface_create(svg.c_str(), width, height), cairo_surface_destroy);
    paint_page(surface.get(), paint, svg);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), svg);
  }
  return {png.filename().string(), svg.filename().string()};
}

void centred_text(cairo_t* cr, const std::string& text, double x, double y, double size) {
  show_text(cr, text, x, y, size, 0.5);
}

void left_text(cairo_t* cr, const std::string& text, double x, double y, double size) {
  show_text(cr, text, x, y, size, 0);
}

}  // namespace affinterp::plots
