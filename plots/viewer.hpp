#pragma once
// An interactive viewer of interpolations: one self-contained HTML page (data and script inlined, nothing
// fetched) with a time slider, play/pause, triangles coloured by a per-triangle measure of B_i (Kaji eq. (1):
// area ratio det B_i, distortion σ1/σ2, flipped), a curve over time (per-frame energies when recorded, else
// the per-frame metrics), and several runs side by side on one slider. PAGE.html#frame=K opens at frame K.
// Frames travel as base64 Float32 arrays and are drawn on a canvas, so 66k-triangle meshes stay responsive.
#include "theory/global/mesh.hpp"
#include "theory/global/metrics.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

/// A quantity with one value per frame.
struct FrameSeries {
  std::string name;
  std::vector<double> values;
};

/// One interpolation as the viewer shows it.
struct ViewerRun {
  std::string title;
  global::Mesh source;                        ///< triangles (counter-clockwise) and the rest shape B_i starts from
  std::vector<double> times;                  ///< t of each frame
  std::vector<Eigen::Matrix2Xd> frames;       ///< the vertices of each frame
  std::vector<global::FrameMetrics> metrics;  ///< of each frame (theory/global/metrics.hpp)
  /// Per-frame energies: the minimised energy E(t) first, then its parts for a blend or a symmetrised
  /// energy. Empty when the run did not record them (the viewer then plots `metrics` over time).
  std::vector<FrameSeries> energy;
};

/// Writes `html`, showing `runs` side by side under `title`. Throws std::invalid_argument when a run is
/// inconsistent (no frames, sizes that differ) and std::runtime_error (one line) when the file cannot be
/// written.
void write_viewer(const std::filesystem::path& html, const std::string& title, const std::vector<ViewerRun>& runs);

}  // namespace affinterp::plots
