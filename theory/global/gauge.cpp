#include "theory/global/gauge.hpp"

#include <limits>

namespace affinterp::global {

std::optional<EdgeDirection> default_edge_direction(const Mesh& source, const InterpolationOptions& options) {
  const Constraints& given = options.constraints;
  // E^F is not invariant under scaling; a caller who constrains a vertex or an edge chooses the gauge
  // (and the engine refuses one that leaves the collapse: well_posedness.hpp)
  if (options.energy == Energy::frobenius || !given.pinned.empty() || !given.loci.empty() || !given.edges.empty())
    return std::nullopt;
  const Eigen::Vector2d barycentre = source.vertices.rowwise().mean();  // Σ p_k / n
  Eigen::Index nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) {
    const double d = ((source.corner(i, 0) + source.corner(i, 1) + source.corner(i, 2)) / 3 - barycentre).squaredNorm();
    if (d < best) best = d, nearest = i;
  }
  // c ‖v_i(t) − v_j(t) − A_τ(t)(p_i − p_j)‖², c = 1: Kaji §4's edge constraint on corners 0, 1 of τ
  return EdgeDirection{source.triangles(0, nearest), source.triangles(1, nearest), EdgeDirection::Path::local_homotopy,
                       1.0};
}

}  // namespace affinterp::global
