// quality_3d: the 3D engine's frames against baselines (experiments/measurements/engine3_quality.hpp) on the pose
// pairs the project has: CGAL's elephant (libcgal-demo) to its bend and to its twist (demo_poses.hpp), and cat-0 to
// each other cat pose of Sumner and Popović ("Deformation transfer for triangle meshes", SIGGRAPH 2004) when
// ../shared/data has them. Not a timing: its numbers are the same on every run. Writes one JSON file, which
// `affinterp claims` reads into the report's 3D section, with the piece of surface around the worst inversion of
// exp-log's frames, which it draws there (engine3_closeup.hpp).
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "experiments/measurements/engine3_quality.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;
using affinterp::measurements::PosePair;

std::vector<PosePair> pose_pairs() {
  namespace shapes3d = affinterp::shapes3d;
  std::vector<PosePair> pairs;
  if (const auto elephant = shapes3d::elephant_poses(fs::temp_directory_path() / "affinterp-cgal-demo")) {
    pairs.push_back({"elephant → bent", (*elephant)[0], (*elephant)[1]});
    pairs.push_back({"elephant → twisted", (*elephant)[0], (*elephant)[2]});
  } else {
    std::cerr << "note: libcgal-demo's data is not installed: no elephant pairs\n";
  }
  if (const auto cat = shapes3d::cat_poses({0, 1, 2, 3, 4, 5, 6, 7, 8, 9})) {
    for (int k = 1; k < 10; ++k)
      pairs.push_back({"cat-0 → cat-" + std::to_string(k), (*cat)[0], (*cat)[static_cast<std::size_t>(k)]});
  } else {
    std::cerr << "note: ../shared/data/meshes3d/cat is not present: no cat pairs\n";
  }
  return pairs;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "The 3D engine's frames against baselines (per-vertex linear blend, the deformation stand-in, E^F with "
      "each local homotopy, exp-log symmetrised): the most elements inverted in a frame and the worst mean "
      "distortion, per pose pair; and exp-log's worst inversion up close",
      "quality_3d");
  std::string out = "reports/bench/quality_3d.json";
  int frames = 21;
  app.add_option("--out", out, "The JSON file to write (replaced only when the run succeeds)")->capture_default_str();
  app.add_option("--frames", frames, "Frames per pair, t = 0, 1/(N-1), ..., 1")
      ->check(CLI::Range(2, 1001))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<PosePair> pairs = pose_pairs();
    if (pairs.empty()) throw std::runtime_error("no pose pairs: neither libcgal-demo's data nor the cat poses");
    const auto quality = affinterp::measurements::engine3_quality(
        pairs, frames, [](const std::string& name) { std::cerr << "quality_3d: " << name << "\n"; });
    const fs::path file(out), staging = fs::path(out + ".tmp");
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    std::ofstream(staging) << nlohmann::json(quality).dump(1) << "\n";
    fs::rename(staging, file);
  } catch (const std::exception& e) {
    std::cerr << "quality_3d: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
