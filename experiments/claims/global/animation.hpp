#pragma once
// An interpolation sampled at evenly spaced frames with the per-frame metrics that decide the figure
// claims (flips, min det B_i, distortion) and the minimised energy, and the drawing of its filmstrip, metric
// curves and interactive viewer.
#include "experiments/claims/context.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/metrics.hpp"

#include <string>
#include <vector>

namespace affinterp::claims::global_figures {

struct Animation {
  std::string label;  ///< e.g. "E^F"
  std::vector<double> t;
  std::vector<Eigen::Matrix2Xd> frames;
  std::vector<global::FrameMetrics> metrics;
  std::vector<double> energy;  ///< E_t (Kaji §4) at each frame: what the interpolation minimised

  Eigen::Index most_flips() const;  ///< max over frames of the flipped-triangle count
  double min_det() const;           ///< min over frames of min_i det B_i(t)
};

/// Frames at t = 0, 1/(count−1), …, 1.
Animation animate(const std::string& label, const global::Mesh& source, const global::Interpolation& interpolation,
                  int count);

/// The vertex of `mesh` farthest in the direction `direction` (ties: the lowest index).
Eigen::Index extreme_vertex(const global::Mesh& mesh, const Eigen::Vector2d& direction);

/// Draws a filmstrip per animation (frames at the given indices) and one chart of min det B_i(t) and the
/// flip count against t for all of them, and writes `name`-viewer.html showing all of them side by side
/// (plots/viewer.hpp); returns the figure references for Outcome::figures (the viewer's last).
std::vector<std::string> draw_animations(const RunSettings& ctx, const std::string& name, const global::Mesh& source,
                                         const std::vector<Animation>& animations, const std::vector<int>& shown_frames,
                                         const std::string& title);

/// The largest distance over frames and loci between a locus vertex v_k(t) and its prescribed u_k(t).
double worst_locus_distance(const Animation& animation, const std::vector<global::VertexLocus>& loci);

/// Draws, per animation, the frames at `shown_frames` superimposed with each prescribed locus u_k(t) (its
/// points marked) and the path v_k(t) the vertex took over all frames; returns the figure references.
std::vector<std::string> draw_loci_overlays(const RunSettings& ctx, const std::string& name, const global::Mesh& source,
                                            const std::vector<Animation>& animations,
                                            const std::vector<global::VertexLocus>& loci,
                                            const std::vector<int>& shown_frames, const std::string& title);

}  // namespace affinterp::claims::global_figures
