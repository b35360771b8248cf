#pragma once
// Reading a closed 2D outline (a polygon's vertices in order) for `affinterp pair`:
//   plain text  one `x y` vertex per line; blank lines and `#` comments skipped;
//   SVG         the first <polygon> or <polyline> (its `points`) or <path> (its `d`, straight segments
//               only: M L H V Z, absolute or relative; curves are refused), in the file's coordinates
//               with y flipped (SVG's y points down) so that the shape appears as drawn.
// A last vertex equal to the first (an explicitly closed outline) is dropped. Errors are MeshFileError
// with one line naming the file (and the line for text).
#include "experiments/inputs/mesh_file.hpp"

#include <Eigen/Core>

namespace affinterp::io {

/// Parses outline text (plain or SVG, decided by a leading '<'); `name` starts the messages.
Eigen::Matrix2Xd parse_outline(std::string_view text, const std::string& name);
/// Reads `file` with parse_outline.
Eigen::Matrix2Xd read_outline(const std::filesystem::path& file);

}  // namespace affinterp::io
