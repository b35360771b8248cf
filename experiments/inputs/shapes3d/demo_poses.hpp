#pragma once
// Poses of real 3D surfaces for the 3D claims, figures and benchmarks: a CGAL demo mesh (libcgal-demo) with a
// bend and a twist the project applies itself, and the cat poses of Sumner and Popović ("Deformation transfer for
// triangle meshes", SIGGRAPH 2004) when ../shared/data has them.
#include "theory/deformation/mesh3.hpp"
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace affinterp::shapes3d {

/// The same surface as an element mesh of theory/global3.
global3::Mesh3 from_surface(const sym3::Mesh3& surface);
/// 1→4 midpoint subdivision of a triangle mesh (sym3::midpoint_subdivision).
global3::Mesh3 subdivided(const global3::Mesh3& surface);

/// Bent in the plane of the bounding box's two longest sides: the long axis through the box's centre becomes an
/// arc turning by `angle` per half length (each cross-section follows it, a beam's bend).
global3::Mesh3 bent_about_centre(const global3::Mesh3& mesh, double angle);
/// Twisted about the longest side's axis through the box's centre: a point at s ∈ [−1, 1] along it turns by
/// s·`turn`.
global3::Mesh3 twisted_about_long_axis(const global3::Mesh3& mesh, double turn);

/// CGAL's elephant.off (2,775 vertices, 5,558 triangles) as three poses: rest, bent by π/3 per half length,
/// twisted by π/2 per half length. Extracted into `folder`; nullopt when libcgal-demo is not installed.
std::optional<std::vector<global3::Mesh3>> elephant_poses(const std::filesystem::path& folder);

/// The folder of the cat poses (cat-0.off … cat-9.off), or nullopt when ../shared/data has none.
std::optional<std::filesystem::path> cat_folder();
/// The cat poses numbered `which`, or nullopt when the folder is absent. Throws std::runtime_error (one line)
/// when a present file cannot be read.
std::optional<std::vector<global3::Mesh3>> cat_poses(const std::vector<int>& which);

}  // namespace affinterp::shapes3d
