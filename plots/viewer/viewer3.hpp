#pragma once
// The 3D viewer: one self-contained HTML page (WebGL through three.js and its OrbitControls from Debian's
// libjs-three, inlined when the page is written, with the frames; nothing fetched), a frame slider (times, or a
// blend's weight vectors), orbiting, and faces coloured by their in-plane distortion or by inverted elements. A
// tetrahedral mesh is drawn by its boundary faces. The page's template is plots/viewer/viewer3.html.
//
// The page does not judge inversion itself: a triangle in space has no sign of its own, and whether it is inverted
// depends on the map its frame is measured against (frame_metrics3.hpp), which the page does not have. The writer
// hands it each frame's inverted elements as metrics.json counts them.
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace affinterp::plots {

struct Viewer3Frame {
  std::string label;  ///< shown beside the slider, e.g. "t = 0.5" or "w = (0.2, 0.5, 0.3)"
  Eigen::Matrix3Xd vertices;
  /// The frame's inverted elements (FrameMetrics3::inverted); when any frame has none measured, the page offers no
  /// colouring by inverted elements.
  std::optional<std::vector<Eigen::Index>> inverted;
};

/// Where three.js is read from: $AFFINTERP_THREE_DIR, else Debian's /usr/share/javascript/three.
std::filesystem::path three_js_folder();

/// Writes `html` showing `frames` of `rest`'s elements; inverted elements that `near_folds` marks (empty, or one
/// entry an element: target_folds3.hpp's near_folds) are drawn apart, as the input's. Throws std::runtime_error
/// (one line) when three.js is not installed or the page cannot be written.
void write_viewer3(const std::filesystem::path& html, const std::string& title, const global3::Mesh3& rest,
                   const std::vector<Viewer3Frame>& frames, std::span<const unsigned char> near_folds = {});

}  // namespace affinterp::plots
