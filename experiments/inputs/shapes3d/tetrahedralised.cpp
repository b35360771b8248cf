#include "experiments/inputs/shapes3d/tetrahedralised.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace affinterp::shapes3d {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

/// The tetrahedra of the complex's cells, their vertices numbered in order of first use, each oriented positively.
global3::Mesh3 tetrahedra_of(const Complex& complex) {
  std::map<Triangulation::Vertex_handle, int> index;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector4i> cells;
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell) {
    Eigen::Vector4i corners;
    for (int c = 0; c < 4; ++c) {
      const auto [it, added] = index.emplace(cell->vertex(c), static_cast<int>(points.size()));
      if (added) {
        const auto& p = cell->vertex(c)->point().point();
        points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      corners[c] = it->second;
    }
    cells.push_back(corners);
  }
  global3::Mesh3 mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) mesh.vertices.col(static_cast<Eigen::Index>(k)) = points[k];
  mesh.elements.resize(4, static_cast<Eigen::Index>(cells.size()));
  for (std::size_t i = 0; i < cells.size(); ++i) mesh.elements.col(static_cast<Eigen::Index>(i)) = cells[i];
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i) {  // det [p1 − p0, p2 − p0, p3 − p0] > 0
    Eigen::Matrix3d E;
    for (int c = 1; c < 4; ++c) E.col(c - 1) = mesh.corner(i, c) - mesh.corner(i, 0);
    if (E.determinant() < 0) std::swap(mesh.elements(1, i), mesh.elements(2, i));
  }
  return mesh;
}

}  // namespace

global3::Mesh3 tetrahedralised_capsule(double length, double cell_size) {
  constexpr double radius = 0.5;
  // Negative inside: the distance to the axis segment less the radius.
  const auto capsule = [length](const K::Point_3& q) {
    const double x = std::clamp(q.x(), 0.0, length);
    return std::hypot(q.x() - x, q.y(), q.z()) - radius;
  };
  const double reach = length / 2 + radius + 0.1;
  CGAL::Random seeded(2012);
  namespace p = CGAL::parameters;
  const Domain domain =
      Domain::create_implicit_mesh_domain(capsule, K::Sphere_3(K::Point_3(length / 2, 0, 0), reach * reach),
                                          p::relative_error_bound = 1e-6, p::p_rng = &seeded);
  const Criteria criteria(p::facet_angle = 25, p::facet_size = cell_size, p::facet_distance = cell_size / 8,
                          p::cell_radius_edge_ratio = 3, p::cell_size = cell_size);
  const Complex complex = CGAL::make_mesh_3<Complex>(domain, criteria, p::no_perturb(), p::exude(p::sliver_bound = 10));
  return tetrahedra_of(complex);
}

}  // namespace affinterp::shapes3d
