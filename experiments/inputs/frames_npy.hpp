#pragma once
// Frames of an interpolation as one NumPy .npy array (format version 1.0): float64, little-endian, shape
// (frames, vertices, d) for d = 2 (plane) or 3 (space), C order, so that numpy.load gives frames[k, j] = the
// coordinates of vertex j at frame k. The binary output of `affinterp interpolate --format npy` (and `blend`)
// for large meshes: 8d bytes a vertex, written as each frame arrives, where an OBJ frame takes about 20d bytes a
// vertex and its number formatting.
#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <fstream>

namespace affinterp::io {

class NpyFrameWriter {
 public:
  /// Creates `file` with the header for `frames` frames of `vertices` vertices of `dimension` coordinates;
  /// throws MeshFileError when it cannot be written.
  NpyFrameWriter(const std::filesystem::path& file, std::size_t frames, Eigen::Index vertices, int dimension = 2);
  /// Appends the next frame (dimension × vertices); throws std::invalid_argument on a wrong size or one frame too
  /// many.
  void append(const Eigen::Ref<const Eigen::MatrixXd>& frame);
  /// Flushes; throws MeshFileError unless every announced frame was appended and written.
  void close();

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  std::size_t frames_, written_ = 0;
  Eigen::Index vertices_;
  int dimension_;
};

}  // namespace affinterp::io
