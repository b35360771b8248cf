#include "theory/global/gauge.hpp"

#include <limits>

namespace affinterp::global {
namespace {

/// ‖c_τ − p̄‖² / r² for every triangle τ of one mesh (gauge.hpp).
Eigen::VectorXd centrality(const Mesh& mesh) {
  const Eigen::Vector2d barycentre = mesh.vertices.rowwise().mean();  // Σ p_k / n
  const double spread = (mesh.vertices.colwise() - barycentre).squaredNorm() / static_cast<double>(mesh.vertex_count());
  Eigen::VectorXd d(mesh.triangle_count());
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i)
    d[i] = ((mesh.corner(i, 0) + mesh.corner(i, 1) + mesh.corner(i, 2)) / 3 - barycentre).squaredNorm() / spread;
  return d;
}

}  // namespace

std::optional<EdgeDirection> default_edge_direction(const Mesh& source, const Mesh& target,
                                                    const InterpolationOptions& options) {
  const Constraints& given = options.constraints;
  // E^F is not invariant under scaling; a caller who constrains a vertex or an edge chooses the gauge
  // (and the engine refuses one that leaves the collapse: well_posedness.hpp)
  if (options.energy == Energy::F || !given.pinned.empty() || !given.loci.empty() || !given.edges.empty())
    return std::nullopt;
  // a + b = b + a exactly in floating point: (Q, P) scores every triangle as (P, Q) does
  const Eigen::VectorXd score = centrality(source) + centrality(target);
  Eigen::Index nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < score.size(); ++i)
    if (score[i] < best) best = score[i], nearest = i;
  // c ‖v_i(t) − v_j(t) − A_τ(t)(p_i − p_j)‖², c = 1: Kaji §4's edge constraint on corners 0, 1 of τ
  return EdgeDirection{source.triangles(0, nearest), source.triangles(1, nearest), EdgeDirection::Path::local_homotopy,
                       1.0};
}

}  // namespace affinterp::global
