#pragma once
// What makes meshes valid input of the 3D engine: every element's linear map A_i (element_maps3.hpp) exists and
// lies in GL⁺(3), and the minimiser of E^F (poisson_system3.hpp) is unique up to the translation its
// constraints fix. Each rule throws global::InvalidMesh (a global::RefusedProblem) with a one-line message naming
// the element or vertex (0-based).
//
// Not refused, as nothing here needs them: non-manifold edges and vertices, and triangles oriented unlike their
// neighbours (each A_i uses its own triangle's normal in both poses). One consequence to know: the consistent
// rotation branch walks from element to element through shared facets (rotation_branches3.hpp), so pieces that
// meet only at a vertex, connected for E^F, each start their own walk at the principal branch.
#include "theory/global/mesh_validation.hpp"
#include "theory/global3/mesh3.hpp"

#include <string>

namespace affinterp::global3 {

/// Unless the mesh has a vertex and an element, 3 or 4 rows of indices, finite coordinates, and elements of
/// distinct in-range vertices.
void check_well_formed(const Mesh3& mesh);

/// Unless `pose` has the vertex count and the element list of `reference` (the first difference is named).
void check_compatible(const Mesh3& reference, const Mesh3& pose);

/// Unless every vertex belongs to an element and the elements are in one piece (joined through shared
/// vertices): E^F depends on each element's edges only, so a second piece would translate freely and the
/// minimiser would not be unique up to the barycentre's gauge.
void check_connected(const Mesh3& mesh);

/// Unless every element is non-degenerate (triangles: area above the rounding level of their longest edge
/// squared; tetrahedra: volume above that of the longest edge cubed) and every tetrahedron positively
/// oriented (det [p1−p0 p2−p0 p3−p0] > 0, so that A_i ∈ GL⁺(3)); `which` names the mesh in the message.
void check_elements(const Mesh3& mesh, const std::string& which);

/// check_well_formed, check_connected and check_elements: the rules for the source or rest mesh, named `which`.
void check_reference(const Mesh3& reference, const char* which);
/// check_compatible with the reference, finite coordinates and check_elements: the rules for a target or pose named
/// `which`.
void check_pose(const Mesh3& reference, const Mesh3& pose, const std::string& which);

}  // namespace affinterp::global3
