#include "theory/global/constraint_terms.hpp"

#include "theory/global/locus.hpp"
#include "theory/global/refused_problem.hpp"

#include <cmath>
#include <string>

namespace affinterp::global {
namespace {

void require_vertex(const Mesh& mesh, Eigen::Index k, const std::string& what) {
  if (k < 0 || k >= mesh.vertex_count())
    throw RefusedProblem(what + ": vertex " + std::to_string(k) + " does not exist (the mesh has " +
                         std::to_string(mesh.vertex_count()) + " vertices)");
}

void require_weight(double c, const std::string& what) {
  if (!(c > 0) || !std::isfinite(c)) throw RefusedProblem(what + ": the weight must be positive and finite");
}

/// The first triangle holding the edge {i, j}, or −1.
Eigen::Index triangle_with_edge(const Mesh& mesh, Eigen::Index i, Eigen::Index j) {
  for (Eigen::Index t = 0; t < mesh.triangle_count(); ++t) {
    const auto corners = mesh.triangles.col(t);
    if ((corners.array() == i).any() && (corners.array() == j).any()) return t;
  }
  return -1;
}

}  // namespace

std::vector<ConstraintTerm> constraint_terms(const Constraints& constraints, const Mesh& source, const Mesh& target,
                                             const LocalPaths& paths) {
  std::vector<ConstraintTerm> terms;
  for (const PinnedVertex& pin : constraints.pinned) {
    const std::string name = "pinned vertex " + std::to_string(pin.vertex);
    require_vertex(source, pin.vertex, name);
    require_weight(pin.weight, name);
    const Eigen::Vector2d p = source.vertices.col(pin.vertex), q = target.vertices.col(pin.vertex);
    terms.push_back(
        {{{pin.vertex, 1.0}}, pin.weight, [p, q](double t) -> Eigen::Vector2d { return (1 - t) * p + t * q; }, name});
  }
  for (const VertexLocus& locus : constraints.loci) {
    const std::string name = "locus of vertex " + std::to_string(locus.vertex);
    require_vertex(source, locus.vertex, name);
    require_weight(locus.weight, name);
    try {
      terms.push_back(
          {{{locus.vertex, 1.0}}, locus.weight, [u = Locus(locus.points)](double t) { return u.at(t); }, name});
    } catch (const std::invalid_argument& e) {
      throw RefusedProblem(name + ": " + e.what());
    }
  }
  for (const EdgeDirection& edge : constraints.edges) {
    const std::string name = "direction of edge " + std::to_string(edge.i) + "-" + std::to_string(edge.j);
    require_vertex(source, edge.i, name);
    require_vertex(source, edge.j, name);
    require_weight(edge.weight, name);
    if (edge.i == edge.j) throw RefusedProblem(name + ": the two ends are the same vertex");
    const Eigen::Vector2d p = source.vertices.col(edge.i) - source.vertices.col(edge.j);
    const Eigen::Vector2d q = target.vertices.col(edge.i) - target.vertices.col(edge.j);
    std::function<Eigen::Vector2d(double)> e;
    if (edge.path == EdgeDirection::Path::linear) {
      e = [p, q](double t) -> Eigen::Vector2d { return (1 - t) * p + t * q; };
    } else {
      const Eigen::Index tau = triangle_with_edge(source, edge.i, edge.j);
      if (tau < 0) throw RefusedProblem(name + ": no triangle has this edge, so no local homotopy rotates it");
      e = [p, tau, &paths](double t) -> Eigen::Vector2d { return paths.at(tau, t) * p; };
    }
    terms.push_back({{{edge.i, 1.0}, {edge.j, -1.0}}, edge.weight, std::move(e), name});
  }
  if (constraints.barycentre) {
    const BarycentreLocus& b = *constraints.barycentre;
    require_weight(b.weight, "barycentre locus");
    const Eigen::Index n = source.vertex_count();
    ConstraintTerm term{{}, b.weight, {}, "barycentre locus"};
    for (Eigen::Index k = 0; k < n; ++k) term.coefficients.emplace_back(k, 1.0 / static_cast<double>(n));
    Eigen::Matrix2Xd points = b.points;
    if (points.cols() == 0) {
      points.resize(2, 2);
      points.col(0) = source.vertices.rowwise().mean();
      points.col(1) = target.vertices.rowwise().mean();
    }
    try {
      term.target = [u = Locus(points)](double t) { return u.at(t); };
    } catch (const std::invalid_argument& e) {
      throw RefusedProblem(std::string("barycentre locus: ") + e.what());
    }
    terms.push_back(std::move(term));
  }
  return terms;
}

}  // namespace affinterp::global
