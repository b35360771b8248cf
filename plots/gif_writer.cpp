#include "plots/gif_writer.hpp"

#include <fcntl.h>
#include <gif_lib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace affinterp::plots {

namespace fs = std::filesystem;

struct GifWriter::Gif {
  GifFileType* file = nullptr;
  ~Gif() {
    if (file) EGifCloseFile(file, nullptr);  // after an error: finish() reports errors of a good run
  }
};

namespace {

[[noreturn]] void fail(const fs::path& file, int error) {
  const char* text = GifErrorString(error);
  throw std::runtime_error("cannot write " + file.string() + ": " +
                           (text ? text : "giflib error " + std::to_string(error)));
}

std::uint8_t channel(double x) { return static_cast<std::uint8_t>(std::clamp(x, 0.0, 1.0) * 255 + 0.5); }

}  // namespace

GifWriter::GifWriter(const fs::path& file, int width, int height, const std::vector<Colour>& palette, int delay_cs)
    : file_(file),
      width_(width),
      height_(height),
      delay_cs_(delay_cs),
      row_(static_cast<std::size_t>(width)),
      gif_(std::make_unique<Gif>()) {
  if (palette.empty() || palette.size() > 256) throw std::runtime_error("GifWriter: a palette needs 1 to 256 colours");
  int bits = 1;
  while ((1u << bits) < palette.size()) ++bits;
  ColorMapObject* map = GifMakeMapObject(1 << bits, nullptr);
  for (std::size_t c = 0; c < palette.size(); ++c)
    map->Colors[c] = {channel(palette[c].r), channel(palette[c].g), channel(palette[c].b)};
  nearest_.resize(1 << 15);
  for (int key = 0; key < (1 << 15); ++key) {
    const int r = ((key >> 10) & 31) * 255 / 31, g = ((key >> 5) & 31) * 255 / 31, b = (key & 31) * 255 / 31;
    int best = std::numeric_limits<int>::max();
    for (std::size_t c = 0; c < palette.size(); ++c) {
      const GifColorType p = map->Colors[c];
      const int d = (r - p.Red) * (r - p.Red) + (g - p.Green) * (g - p.Green) + (b - p.Blue) * (b - p.Blue);
      if (d < best) best = d, nearest_[static_cast<std::size_t>(key)] = static_cast<std::uint8_t>(c);
    }
  }
  // Opened here rather than by EGifOpenFileName, which creates files readable by their owner alone.
  const int descriptor = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (descriptor < 0) {
    GifFreeMapObject(map);
    throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
  }
  int error = 0;
  gif_->file = EGifOpenFileHandle(descriptor, &error);
  if (!gif_->file) {
    close(descriptor);
    GifFreeMapObject(map);
    fail(file, error);
  }
  EGifSetGifVersion(gif_->file, true);
  const int status = EGifPutScreenDesc(gif_->file, width, height, bits, 0, map);
  GifFreeMapObject(map);
  static const char netscape[] = "NETSCAPE2.0";
  const unsigned char loop_forever[3] = {1, 0, 0};
  if (status == GIF_ERROR || EGifPutExtensionLeader(gif_->file, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_->file, 11, netscape) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_->file, 3, loop_forever) == GIF_ERROR ||
      EGifPutExtensionTrailer(gif_->file) == GIF_ERROR)
    fail(file, gif_->file->Error);
}

GifWriter::~GifWriter() = default;

void GifWriter::add_frame(const unsigned char* pixels, int stride) {
  GraphicsControlBlock control{DISPOSE_DO_NOT, false, delay_cs_, NO_TRANSPARENT_COLOR};
  GifByteType extension[4];
  EGifGCBToExtension(&control, extension);
  if (EGifPutExtension(gif_->file, GRAPHICS_EXT_FUNC_CODE, 4, extension) == GIF_ERROR ||
      EGifPutImageDesc(gif_->file, 0, 0, width_, height_, false, nullptr) == GIF_ERROR)
    fail(file_, gif_->file->Error);
  for (int y = 0; y < height_; ++y) {
    std::uint32_t pixel;
    for (int x = 0; x < width_; ++x) {
      std::memcpy(&pixel, pixels + static_cast<std::ptrdiff_t>(y) * stride + 4 * x, 4);
      const std::uint32_t key = ((pixel >> 9) & 0x7c00) | ((pixel >> 6) & 0x3e0) | ((pixel >> 3) & 0x1f);
      row_[static_cast<std::size_t>(x)] = nearest_[key];
    }
    if (EGifPutLine(gif_->file, row_.data(), width_) == GIF_ERROR) fail(file_, gif_->file->Error);
  }
}

void GifWriter::finish() {
  int error = 0;
  GifFileType* file = gif_->file;
  gif_->file = nullptr;
  if (EGifCloseFile(file, &error) == GIF_ERROR) fail(file_, error);
}

}  // namespace affinterp::plots
