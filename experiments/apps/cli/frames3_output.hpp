#pragma once
// What a 3D run of `affinterp interpolate` or `affinterp blend` writes per frame: the frame's file (OBJ for a
// surface, MEDIT .mesh for tetrahedra, or one frames.npy of shape (frames, n, 3) for all) and its entry in
// metrics.json (theory/global3/frame_metrics3.hpp against the source or rest mesh and the frame's local maps).
#include "experiments/inputs/frames_npy.hpp"
#include "experiments/support/staged_output.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/mesh3.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace affinterp::cli {

class Frames3Output {
 public:
  /// Frames of `reference`'s elements into `staging`; `format` is obj (one file a frame) or npy. With `reoriented`
  /// (io::Poses3::reoriented) the frame files keep the input files' corner order.
  Frames3Output(const std::filesystem::path& staging, const global3::Mesh3& reference, std::size_t frame_count,
                const std::string& format, bool reoriented = false);
  /// Writes frame k and returns its metrics.json entry: index, file, and with `quality` the metrics of
  /// frame_metrics3 (inversion judged against `local_maps`), whose inverted elements it keeps for the viewer.
  nlohmann::json record(int k, const Eigen::Matrix3Xd& vertices, std::span<const Eigen::Matrix3d> local_maps,
                        bool quality);
  /// From now on, the quality metrics also count the inverted elements `near` marks (target_folds3.hpp's
  /// near_folds) as "inverted_near_folds".
  void count_near_folds(std::vector<unsigned char> near) { near_folds_ = std::move(near); }
  /// Ends frames.npy; throws MeshFileError when a frame is missing.
  void close();

  /// Per frame recorded with `quality`, in order, its inverted elements (FrameMetrics3::inverted).
  const std::vector<std::vector<Eigen::Index>>& inverted() const { return inverted_; }
  /// The mask given to count_near_folds, or empty.
  const std::vector<unsigned char>& near_folds() const { return near_folds_; }

 private:
  std::filesystem::path staging_;
  global3::Mesh3 frame_;
  const global3::Mesh3& reference_;
  std::optional<io::NpyFrameWriter> npy_;
  std::vector<unsigned char> near_folds_;
  std::vector<std::vector<Eigen::Index>> inverted_;
};

/// The closing line's account of metrics.json's "frames": "most inverted elements in a frame: N" (0 without quality
/// metrics), and where frames count "inverted_near_folds", "; away from <whose> folds: M", the most of them in a
/// frame that are not.
std::string inverted_summary(const nlohmann::json& frames, const std::string& whose);

/// OUT/viewer.html of `frames` (labelled by `labels`) into `folder`, with the inverted elements `measured` recorded
/// (when it recorded every frame with quality metrics), or a note on standard error when the viewer cannot be
/// written (three.js not installed): the frames stand without it.
void write_viewer3_or_note(const std::filesystem::path& folder, const std::string& title, const global3::Mesh3& rest,
                           const std::vector<Eigen::Matrix3Xd>& frames, const std::vector<std::string>& labels,
                           const Frames3Output& measured);

/// Moves the staged files into `out`, first removing earlier frame files (frame_*.obj, frame_*.mesh, frames.npy)
/// that this run does not replace, which would mix two runs.
void commit_frames3(StagedOutput& staged, const std::filesystem::path& out);

}  // namespace affinterp::cli
