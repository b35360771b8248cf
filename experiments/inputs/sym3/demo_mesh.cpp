#include "experiments/inputs/sym3/demo_mesh.hpp"

#include "experiments/inputs/mesh_file.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace affinterp::sym3 {

namespace fs = std::filesystem;

std::optional<Mesh3> cgal_demo_mesh(std::string_view name, const fs::path& folder) {
  if (!fs::exists(cgal_demo_archive)) return std::nullopt;
  const fs::path file = folder / "data" / "meshes" / name;
  if (!fs::exists(file)) {
    fs::create_directories(folder);
    const std::string command = "tar -xzf '" + std::string(cgal_demo_archive) + "' -C '" + folder.string() +
                                "' 'data/meshes/" + std::string(name) + "'";
    if (std::system(command.c_str()) != 0 || !fs::exists(file))
      throw std::runtime_error("could not extract data/meshes/" + std::string(name) + " from " +
                               std::string(cgal_demo_archive));
  }
  return io::read_off_surface(file);
}

std::optional<Mesh3> dragon_mesh(const fs::path& folder) {
  auto mesh = cgal_demo_mesh("ChineseDragon-10kv.off", folder);
  if (!mesh) return std::nullopt;
  return midpoint_subdivision(*mesh);
}

}  // namespace affinterp::sym3
