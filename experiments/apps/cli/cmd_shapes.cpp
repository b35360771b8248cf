// `affinterp shapes`: write the project's generated source/target mesh pairs as OBJ files.
#include "experiments/apps/cli/command.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"
#include "experiments/support/staged_output.hpp"

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

void run(const ShapesOptions& options) {
  if (options.list) {
    for (const auto& shape : shapes::shape_catalogue()) std::cout << shape.name << "\t" << shape.description << "\n";
    return;
  }
  if (options.name.empty() || options.out.empty())
    throw CommandFailed("give a shape NAME and --out DIR (or --list)", usage_error);
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
  CLI::App* cmd =
      app.add_subcommand("shapes", "Write a generated source/target mesh pair (OUT/source.obj, OUT/target.obj).");
  cmd->add_option("name", options->name, "Shape pair name (see --list)");
  cmd->add_flag("--list", options->list, "List the shape pairs with a description, then exit");
  cmd->add_option("--out", options->out, "Folder for source.obj and target.obj");
  cmd->add_option("--seed", options->seed, "Seed of the 'random' pair")->capture_default_str();
  cmd->add_option("--quads", options->quads,
                  "COLSxROWS: the resolution of 'strip-spiral' (default 200x25; 2000x250 is the 1M-triangle case)");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
