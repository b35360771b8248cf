#pragma once
// An animated GIF (GIF89a, looping) written in-process with giflib, from 32-bit RGB pixels (Cairo's
// CAIRO_FORMAT_RGB24) quantised through a fixed palette of at most 256 colours: each pixel takes the
// nearest palette colour, looked up in a table over 5 bits a channel built once.
#include "plots/mesh_painter.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace affinterp::plots {

class GifWriter {
 public:
  /// Starts `file`, width × height pixels, each frame shown `delay_cs` hundredths of a second. Throws
  /// std::runtime_error (one line) when the file cannot be opened or the palette has over 256 colours.
  GifWriter(const std::filesystem::path& file, int width, int height, const std::vector<Colour>& palette, int delay_cs);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Appends a frame: height rows of width pixels 0x00RRGGBB, each row `stride` bytes from the last.
  void add_frame(const unsigned char* pixels, int stride);
  /// Writes the trailer and closes the file; throws std::runtime_error on a write error.
  void finish();

 private:
  struct Gif;
  std::filesystem::path file_;
  int width_, height_, delay_cs_;
  std::vector<std::uint8_t> nearest_;  ///< palette index per 15-bit colour
  std::vector<std::uint8_t> row_;
  std::unique_ptr<Gif> gif_;
};

}  // namespace affinterp::plots
