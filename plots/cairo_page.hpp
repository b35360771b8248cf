#pragma once
// Pages drawn in-process with Cairo: the same drawing written as PNG and SVG, and text in the house font
// (DejaVu Sans, as the gnuplot figures).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using cairo_t = struct _cairo;

namespace affinterp::plots {

/// Draws `paint` onto a white page of width × height pixels (points in the SVG) and writes stem.png and
/// stem.svg; returns their file names. Throws std::runtime_error (one line) when a file cannot be written.
std::vector<std::string> render_png_and_svg(const std::filesystem::path& stem, int width, int height,
                                            const std::function<void(cairo_t*)>& paint);

/// `text` in black, `size` pixels high, centred on x with its baseline at y.
void centred_text(cairo_t* cr, const std::string& text, double x, double y, double size);

/// `text` in black, `size` pixels high, starting at x with its baseline at y.
void left_text(cairo_t* cr, const std::string& text, double x, double y, double size);

}  // namespace affinterp::plots
