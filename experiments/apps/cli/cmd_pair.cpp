// `affinterp pair`: compatible meshes from two outlines (experiments/inputs/compatible_pair.hpp): source.obj
// and target.obj with one triangle list and no flipped or degenerate triangle in either.
#include "experiments/apps/cli/command.hpp"
#include "experiments/inputs/compatible_pair.hpp"
#include "experiments/inputs/outline_file.hpp"
#include "experiments/support/staged_output.hpp"

#include <iomanip>
#include <iostream>
#include <memory>

namespace affinterp::cli {

namespace {

struct PairOptions {
  std::string source, target, out;
  int resample = 0;
  int quality_passes = 8;
};

void run(const PairOptions& o) {
  io::CompatiblePair pair;
  try {
    Eigen::Matrix2Xd source = io::read_outline(o.source), target = io::read_outline(o.target);
    if (o.resample > 0)
      source = io::resample_outline(source, o.resample), target = io::resample_outline(target, o.resample);
    pair = io::compatible_pair(source, target, o.source, o.target, o.quality_passes);
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  } catch (const io::OutlineError& e) {
    throw CommandFailed(e.what(), 1);
  }
  StagedOutput staged(o.out);
  io::write_obj(pair.source, staged.staging() / "source.obj");
  io::write_obj(pair.target, staged.staging() / "target.obj");
  staged.commit();
  std::cout << std::fixed << std::setprecision(2) << "wrote " << o.out
            << "/source.obj and target.obj: " << pair.source.vertex_count() << " vertices (" << pair.steiner_vertices
            << " inside), " << pair.source.triangle_count() << " triangles, 0 flipped; smallest angle "
            << pair.source_min_angle << " deg (source), " << pair.target_min_angle << " deg (target)\n";
}

}  // namespace

void add_pair_command(CLI::App& app) {
  auto o = std::make_shared<PairOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pair",
      "Compatible triangle meshes from two simple polygons whose i-th vertices correspond (Aronov, Seidel and "
      "Souvaine 1993): writes OUT/source.obj and OUT/target.obj with one triangle list and, by construction, no "
      "flipped or degenerate triangle in either (both outlines triangulated, mapped onto one convex domain, overlaid "
      "there with exact arithmetic and the common refinement mapped back), then improves the triangles' angles "
      "without creating a flip. Outlines: plain text, one 'x y' vertex per line, or SVG (the first polygon, "
      "polyline or straight-segment path). Prints the vertex and triangle counts and the smallest angle. On any "
      "error OUT keeps its earlier content.");
  cmd->add_option("SOURCE", o->source, "Source outline (.txt or .svg)")->required();
  cmd->add_option("TARGET", o->target, "Target outline, the same number of vertices (or use --resample)")->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--resample", o->resample,
                  "N: first resample both outlines to N vertices at equal arc length from their vertex 0")
      ->check(CLI::Range(3, 100000));
  cmd->add_option("--quality-passes", o->quality_passes, "Rounds of edge flips and smoothing (0: none)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace affinterp::cli
