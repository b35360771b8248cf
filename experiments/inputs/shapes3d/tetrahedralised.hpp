#pragma once
// A solid of tetrahedra meshed by CGAL's Mesh_3 (Delaunay refinement of an implicit domain), the project's own
// tetrahedralised input for the 3D claims: a capsule (a cylinder of radius 1/2 along x with round ends), whose
// twists about the x axis (bar3.hpp's twisted) are exact poses.
#include "theory/global3/mesh3.hpp"

namespace affinterp::shapes3d {

/// The capsule {p : dist(p, segment [0, length] × {0} × {0}) ≤ 1/2} meshed by CGAL::make_mesh_3 with cells of size
/// about `cell_size`, slivers removed by exudation (no perturbation, whose time limit would make the mesh depend on
/// the machine's speed; a fixed random seed: the same mesh on every run), positively oriented. Only the vertices of
/// tetrahedra are kept, renumbered in order of first use.
global3::Mesh3 tetrahedralised_capsule(double length, double cell_size);

}  // namespace affinterp::shapes3d
