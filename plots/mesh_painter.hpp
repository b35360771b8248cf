#pragma once
// A triangle mesh painted in-process with Cairo (PNG, SVG, or pixels for a GIF), for drawings of many
// frames of one mesh: what depends only on the triangle list is computed once.
//
// The shape is filled through its boundary chain ∂(τ_1 + … + τ_m) (each triangle's edges in its own
// orientation, edges met both ways cancelling) under the non-zero winding rule. The winding number is
// additive, so at a point it is the number of counter-clockwise minus clockwise triangles covering it:
// the fill is exactly the union of the triangles wherever none is flipped, at the cost of the boundary
// alone (a 66k-triangle mesh fills as fast as its outline). Flipped triangles (det B_i ≤ 0, the source
// counter-clockwise) are drawn over the edges (every edge up to `all_edges_limit` triangles, the boundary
// alone above: finer edges would only grey the picture), filled and outlined in red, the outline keeping
// the smallest in sight.
#include <Eigen/Core>

#include <utility>
#include <vector>

using cairo_t = struct _cairo;

namespace affinterp::plots {

struct Colour {
  double r, g, b;  ///< in [0, 1]
};

/// `a` + s (`b` − `a`), s in [0, 1].
Colour mix(const Colour& a, const Colour& b, double s);

/// The colours of a painted mesh.
struct MeshColours {
  Colour fill, edge, flipped{0.878, 0.188, 0.188};
};

/// A frame's place in a drawing: data point p goes to the pixel (x0 + scale p.x, y0 − scale p.y).
struct View {
  double scale, x0, y0;
};

/// The largest scale at which the box [lo, hi] fits in width × height pixels.
double fitting_scale(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double width, double height);

/// The view at `scale` that puts the centre of the box [lo, hi] at the pixel (x, y).
View centred(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double scale, double x, double y);

class MeshPainter {
 public:
  /// Above this many triangles only boundary edges are stroked.
  static constexpr Eigen::Index all_edges_limit = 20000;

  /// `triangles`: column i holds triangle i's vertex indices, counter-clockwise in the source.
  explicit MeshPainter(const Eigen::Matrix3Xi& triangles);

  /// Paints the mesh with these vertex positions (columns) onto `cr` through `view`; lines `line_width`
  /// pixels wide. Leaves `cr`'s state as it found it.
  void paint(cairo_t* cr, const Eigen::Matrix2Xd& vertices, const View& view, const MeshColours& colours,
             double line_width = 0.6) const;

  /// Triangles with det ≤ 0 in this frame.
  std::vector<Eigen::Index> flipped(const Eigen::Matrix2Xd& vertices) const;

 private:
  Eigen::Matrix3Xi triangles_;
  bool all_edges_;                                 ///< at most all_edges_limit triangles
  std::vector<std::vector<int>> boundary_cycles_;  ///< ∂ of the triangles' sum as closed vertex cycles
  std::vector<std::pair<int, int>> edges_;         ///< every edge once, when all_edges_
};

}  // namespace affinterp::plots
