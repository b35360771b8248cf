#pragma once
// The 3D viewer: one self-contained HTML page (WebGL through three.js and its OrbitControls from Debian's
// libjs-three, inlined when the page is written, with the frames; nothing fetched), a frame slider (times, or a
// blend's weight vectors), orbiting, and faces coloured by their in-plane distortion or by inverted elements. A
// tetrahedral mesh is drawn by its boundary faces. The page's template is plots/viewer/viewer3.html.
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

struct Viewer3Frame {
  std::string label;  ///< shown beside the slider, e.g. "t = 0.5" or "w = (0.2, 0.5, 0.3)"
  Eigen::Matrix3Xd vertices;
};

/// Where three.js is read from: $AFFINTERP_THREE_DIR, else Debian's /usr/share/javascript/three.
std::filesystem::path three_js_folder();

/// Writes `html` showing `frames` of `rest`'s elements. Throws std::runtime_error (one line) when three.js is
/// not installed or the page cannot be written.
void write_viewer3(const std::filesystem::path& html, const std::string& title, const global3::Mesh3& rest,
                   const std::vector<Viewer3Frame>& frames);

}  // namespace affinterp::plots
