#include "experiments/inputs/shapes/triangulate.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <map>
#include <stdexcept>
#include <string>

namespace affinterp::shapes {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// The mesh of the faces `in_domain` accepts; vertices numbered in the order the faces first use them.
template <class Triangulation, class InDomain>
global::Mesh collect(const Triangulation& tr, InDomain in_domain) {
  std::map<typename Triangulation::Vertex_handle, int> index;
  std::vector<Eigen::Vector2d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (auto face = tr.finite_faces_begin(); face != tr.finite_faces_end(); ++face) {
    if (!in_domain(face)) continue;
    Eigen::Vector3i triangle;
    for (int c = 0; c < 3; ++c) {
      const auto [it, inserted] = index.emplace(face->vertex(c), static_cast<int>(vertices.size()));
      if (inserted) vertices.emplace_back(face->vertex(c)->point().x(), face->vertex(c)->point().y());
      triangle(c) = it->second;
    }
    triangles.push_back(triangle);
  }
  global::Mesh mesh;
  mesh.vertices.resize(2, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t k = 0; k < vertices.size(); ++k) mesh.vertices.col(static_cast<Eigen::Index>(k)) = vertices[k];
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i) mesh.triangles.col(static_cast<Eigen::Index>(i)) = triangles[i];
  return mesh;
}

}  // namespace

global::Mesh triangulate(const Outline& outline, double max_edge, const std::vector<Eigen::Vector2d>& extra_points) {
  using Tds =
      CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K>>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
  CDT cdt;
  std::vector<CDT::Vertex_handle> corners;
  for (const auto& p : outline) corners.push_back(cdt.insert(K::Point_2(p.x(), p.y())));
  for (std::size_t k = 0; k < corners.size(); ++k)
    if (corners[k] == corners[(k + 1) % corners.size()])
      throw std::invalid_argument("triangulate: the outline repeats point " + std::to_string(k));
  for (std::size_t k = 0; k < corners.size(); ++k) cdt.insert_constraint(corners[k], corners[(k + 1) % corners.size()]);
  for (const auto& p : extra_points) cdt.insert(K::Point_2(p.x(), p.y()));
  // Shape bound B = 0.125 = sin² of the smallest angle allowed: about 20.7°.
  CGAL::refine_Delaunay_mesh_2(cdt, CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, max_edge));
  return collect(cdt, [](auto face) { return face->is_in_domain(); });
}

global::Mesh delaunay(const std::vector<Eigen::Vector2d>& points) {
  CGAL::Delaunay_triangulation_2<K> dt;
  for (const auto& p : points) dt.insert(K::Point_2(p.x(), p.y()));
  return collect(dt, [](auto) { return true; });
}

}  // namespace affinterp::shapes
