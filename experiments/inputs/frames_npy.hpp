#pragma once
// Frames of an interpolation as one NumPy .npy array (format version 1.0): float64, little-endian, shape
// (frames, vertices, 2), C order, so that numpy.load gives frames[k, j] = (x, y) of vertex j at frame k.
// The binary output of `affinterp interpolate --format npy` for large meshes: 16 bytes a vertex, written
// as each frame arrives, where an OBJ frame takes about 40 bytes a vertex and its number formatting.
#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <fstream>

namespace affinterp::io {

class NpyFrameWriter {
 public:
  /// Creates `file` with the header for `frames` frames of `vertices` vertices; throws MeshFileError when it
  /// cannot be written.
  NpyFrameWriter(const std::filesystem::path& file, std::size_t frames, Eigen::Index vertices);
  /// Appends the next frame (2 × vertices); throws std::invalid_argument on a wrong size or one frame too many.
  void append(const Eigen::Matrix2Xd& frame);
  /// Flushes; throws MeshFileError unless every announced frame was appended and written.
  void close();

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  std::size_t frames_, written_ = 0;
  Eigen::Index vertices_;
};

}  // namespace affinterp::io
