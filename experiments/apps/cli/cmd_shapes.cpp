// `affinterp shapes`: write the project's generated source/target mesh pairs as OBJ files, and its 3D pose sets
// as OBJ surfaces or MEDIT tetrahedra.
#include "experiments/apps/cli/command.hpp"
#include "experiments/inputs/mesh3_file.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"
#include "experiments/inputs/shapes3d/catalogue3.hpp"
#include "experiments/support/staged_output.hpp"

#include <filesystem>

#include <iostream>
#include <memory>
#include <sstream>

namespace affinterp::cli {

namespace {

struct ShapesOptions {
  bool list = false;
  std::string name;
  std::string out;
  std::uint64_t seed = 1;
  std::string quads;
};

/// "COLSxROWS", each a positive integer, at most 20,000,000 triangles in all.
shapes::StripQuads parse_quads(const std::string& text) {
  shapes::StripQuads quads;
  char x = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> quads.cols >> x >> quads.rows) || x != 'x' || in >> rest || quads.cols < 1 || quads.rows < 1 ||
      2.0 * quads.cols * quads.rows > 2e7)
    throw CommandFailed("--quads '" + text + "': give COLSxROWS, positive, at most 20,000,000 triangles in all",
                        usage_error);
  return quads;
}

/// The 3D pose set `name` as OUT/pose-0.EXT, pose-1.EXT, … (OBJ surfaces, MEDIT .mesh tetrahedra).
void write_shape3(const ShapesOptions& options) {
  std::vector<global3::Mesh3> poses;
  try {
    poses = shapes3d::make_shape3(options.name, std::filesystem::temp_directory_path() / "affinterp-cgal-demo");
  } catch (const std::runtime_error& e) {
    throw CommandFailed(e.what(), 1);
  }
  StagedOutput staged(options.out);
  std::string names;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const std::string file = "pose-" + std::to_string(k) + io::mesh3_extension(poses[k]);
    io::write_mesh3(poses[k], staged.staging() / file);
    names += (k ? ", " : "") + file;
  }
  staged.commit();
  std::cerr << "wrote " << options.out << "/" << names << " (" << poses[0].vertex_count() << " vertices, "
            << poses[0].element_count() << (poses[0].corners() == 4 ? " tetrahedra" : " triangles") << ")\n";
}

void run(const ShapesOptions& options) {
  if (options.list) {
    for (const auto& shape : shapes::shape_catalogue()) std::cout << shape.name << "\t" << shape.description << "\n";
    for (const auto& shape : shapes3d::shape_catalogue3())
      std::cout << shape.name << "\t3D: " << shape.description << "\n";
    return;
  }
  if (options.name.empty() || options.out.empty())
    throw CommandFailed("give a shape NAME and --out DIR (or --list)", usage_error);
  if (shapes3d::is_shape3(options.name)) {
    if (!options.quads.empty()) throw CommandFailed("--quads is the resolution of 'strip-spiral' only", usage_error);
    return write_shape3(options);
  }
  if (!options.quads.empty() && options.name != "strip-spiral")
    throw CommandFailed("--quads is the resolution of 'strip-spiral' only", usage_error);
  shapes::MeshPairShapes pair;
  try {
    pair = shapes::make_shape(options.name, options.seed,
                              options.quads.empty() ? shapes::StripQuads{} : parse_quads(options.quads));
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
  StagedOutput staged(options.out);
  io::write_obj(pair.source, staged.staging() / "source.obj");
  io::write_obj(pair.target, staged.staging() / "target.obj");
  staged.commit();
  std::cerr << "wrote " << options.out << "/source.obj and target.obj (" << pair.source.vertex_count() << " vertices, "
            << pair.source.triangle_count() << " triangles)\n";
}

}  // namespace

void add_shapes_command(CLI::App& app) {
  auto options = std::make_shared<ShapesOptions>();
  CLI::App* cmd = app.add_subcommand("shapes",
                                     "Write a generated source/target mesh pair (OUT/source.obj, OUT/target.obj), or a "
                                     "3D pose set (OUT/pose-0.obj, pose-1.obj, ...; .mesh for tetrahedra).");
  cmd->add_option("name", options->name, "Shape pair name (see --list)");
  cmd->add_flag("--list", options->list, "List the shape pairs with a description, then exit");
  cmd->add_option("--out", options->out, "Folder for source.obj and target.obj (3D: pose-0.obj, pose-1.obj, ...)");
  cmd->add_option("--seed", options->seed, "Seed of the 'random' pair")->capture_default_str();
  cmd->add_option("--quads", options->quads,
                  "COLSxROWS: the resolution of 'strip-spiral' (default 200x25; 2000x250 is the 1M-triangle case)");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
