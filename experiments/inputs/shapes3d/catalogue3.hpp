#pragma once
// The project's generated 3D pose sets, the 3D counterpart of shapes/catalogue.hpp: `affinterp shapes` writes them
// for `affinterp interpolate` (the first two poses) and `affinterp blend` (all of them), the same shapes the 3D
// claims and figures use (bar3.hpp, tetrahedralised.hpp, demo_poses.hpp).
#include "theory/global3/mesh3.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::shapes3d {

struct Shape3Info {
  std::string name;
  std::string description;
};

/// Every 3D pose set's name and a one-line description.
const std::vector<Shape3Info>& shape_catalogue3();

/// Whether `name` is a 3D pose set.
bool is_shape3(const std::string& name);

/// The named poses, the rest pose first. CGAL's demo data is extracted into `demo_folder`. Throws
/// std::invalid_argument for an unknown name and std::runtime_error (one line) when libcgal-demo's data is not
/// installed for a set that needs it.
std::vector<global3::Mesh3> make_shape3(const std::string& name, const std::filesystem::path& demo_folder);

}  // namespace affinterp::shapes3d
