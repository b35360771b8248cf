#include "experiments/inputs/shapes3d/catalogue3.hpp"

#include "experiments/inputs/shapes3d/bar3.hpp"
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "experiments/inputs/shapes3d/tetrahedralised.hpp"

#include <functional>
#include <numbers>
#include <stdexcept>

namespace affinterp::shapes3d {

namespace {

using global3::Mesh3;
constexpr double pi = std::numbers::pi;

struct Entry {
  Shape3Info info;
  std::function<std::vector<Mesh3>(const std::filesystem::path&)> make;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> all{
      {{"bar-3pi",
        "a thin bar of 180 tetrahedra, 10 x 0.1 x 0.1, and the bar twisted by 3 pi (at time t the exact pose is the "
        "bar twisted by 3 pi t)"},
       [](const std::filesystem::path&) {
         const Mesh3 bar = tetrahedral_bar(30, 10, 0.1);
         return std::vector<Mesh3>{bar, twisted(bar, 3 * pi, 10)};
       }},
      {{"tube-poses", "an open tube of 384 triangles along x, twisted by 1.5 pi, and bent"},
       [](const std::filesystem::path&) {
         const Mesh3 tube = triangle_tube(12, 16, 4);
         return std::vector<Mesh3>{tube, twisted(tube, 1.5 * pi, 4), bent(tube, 4)};
       }},
      {{"capsule-poses",
        "a capsule of tetrahedra meshed by CGAL's Mesh_3 (6 long, radius 1/2), twisted by 1.5 pi, and bent"},
       [](const std::filesystem::path&) {
         const Mesh3 capsule = tetrahedralised_capsule(6, 0.25);
         return std::vector<Mesh3>{capsule, twisted(capsule, 1.5 * pi, 6), bent(capsule, 6)};
       }},
      {{"elephant-poses",
        "CGAL's elephant.off (libcgal-demo, 5,558 triangles), bent by pi/3 per half length, and twisted by pi/2"},
       [](const std::filesystem::path& folder) {
         auto poses = elephant_poses(folder);
         if (!poses) throw std::runtime_error("elephant-poses needs libcgal-demo's data (Debian: libcgal-demo)");
         return *poses;
       }},
  };
  return all;
}

}  // namespace

const std::vector<Shape3Info>& shape_catalogue3() {
  static const std::vector<Shape3Info> infos = [] {
    std::vector<Shape3Info> out;
    for (const Entry& e : entries()) out.push_back(e.info);
    return out;
  }();
  return infos;
}

bool is_shape3(const std::string& name) {
  for (const Entry& e : entries())
    if (e.info.name == name) return true;
  return false;
}

std::vector<Mesh3> make_shape3(const std::string& name, const std::filesystem::path& demo_folder) {
  for (const Entry& e : entries())
    if (e.info.name == name) return e.make(demo_folder);
  throw std::invalid_argument("unknown 3D shape '" + name + "'");
}

}  // namespace affinterp::shapes3d
