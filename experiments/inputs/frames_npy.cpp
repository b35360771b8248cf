#include "experiments/inputs/frames_npy.hpp"

#include "experiments/inputs/mesh_file.hpp"

#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace affinterp::io {

NpyFrameWriter::NpyFrameWriter(const std::filesystem::path& file, std::size_t frames, Eigen::Index vertices,
                               int dimension)
    : file_(file), out_(file, std::ios::binary), frames_(frames), vertices_(vertices), dimension_(dimension) {
  static_assert(std::endian::native == std::endian::little, "the .npy header says '<f8'");
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(frames) + ", " +
                       std::to_string(vertices) + ", " + std::to_string(dimension) + "), }";
  // magic, version 1.0, header length; magic + 2 + 2 + header + '\n' padded with spaces to a multiple of 64
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  const auto length = static_cast<std::uint16_t>(header.size());
  out_.write("\x93NUMPY\x01\x00", 8);
  const char length_bytes[2] = {static_cast<char>(length & 0xff), static_cast<char>(length >> 8)};
  out_.write(length_bytes, 2);
  out_ << header;
  if (!out_) throw MeshFileError(file.string() + ": cannot be written");
}

void NpyFrameWriter::append(const Eigen::Ref<const Eigen::MatrixXd>& frame) {
  if (frame.rows() != dimension_ || frame.cols() != vertices_ || written_ == frames_)
    throw std::invalid_argument(file_.string() + ": frame " + std::to_string(written_) + " of " +
                                std::to_string(frame.cols()) + " vertices does not fit the array");
  // column-major d × n is (x0, y0, …, x1, y1, …): the C-order rows of one (n, d) frame
  const auto column_bytes = static_cast<std::streamsize>(sizeof(double) * static_cast<std::size_t>(dimension_));
  if (frame.outerStride() == dimension_)
    out_.write(reinterpret_cast<const char*>(frame.data()), column_bytes * frame.cols());
  else
    for (Eigen::Index j = 0; j < frame.cols(); ++j)
      out_.write(reinterpret_cast<const char*>(frame.col(j).data()), column_bytes);
  ++written_;
}

void NpyFrameWriter::close() {
  if (written_ != frames_ || !out_.flush())
    throw MeshFileError(file_.string() + ": cannot be written (" + std::to_string(written_) + " of " +
                        std::to_string(frames_) + " frames)");
  out_.close();
}

}  // namespace affinterp::io
