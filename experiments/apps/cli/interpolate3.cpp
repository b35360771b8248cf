#include "experiments/apps/cli/interpolate3.hpp"

#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/frames3_output.hpp"
#include "experiments/inputs/constraint_spec.hpp"
#include "experiments/inputs/mesh3_poses.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/global3/target_folds3.hpp"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

/// Interpolation3's options from the request (the names and defaults of theory/global/options.hpp).
global3::Interpolation3Options engine_options3(const io::InterpolationRequest& request, Eigen::Index vertex_count) {
  global3::Interpolation3Options options;
  options.homotopy = request.options.homotopy;
  options.rotation_branch = request.options.rotation_branch;
  options.area_weighted = request.options.area_weighted;
  options.symmetric = request.options.symmetric;
  options.arap_iterations = request.arap_iterations;
  try {
    options.constraints = io::parse_constraints3(request.pins, request.loci, request.barycentre_locus, vertex_count);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
  return options;
}

/// metrics.json's "options", the 2D command's names (io::options_json) with E^F, the only 3D energy.
nlohmann::json options3_json(const Interpolate3Run& run) {
  global::InterpolationOptions used = run.request.options;
  used.energy = global::Energy::F;
  nlohmann::json options = io::options_json(run.request, used);
  options["format"] = run.format, options["metrics"] = run.metrics;
  options["times"] = run.times_given ? nlohmann::json(run.times) : nlohmann::json(nullptr);
  return options;
}

/// Each frame's file and metrics.json entry, through `output`: t, the energy the frame minimises (E^F with the
/// constraints; E^ARAP after --arap-iterations), the quality metrics.
nlohmann::json write_frames(const Interpolate3Run& run, const global3::Interpolation3& interpolation,
                            const std::vector<Eigen::Matrix3Xd>& frames, Frames3Output& output) {
  const bool energy = run.metrics == "all" || run.metrics == "energy";
  const bool quality = run.metrics == "all" || run.metrics == "quality";
  nlohmann::json entries = nlohmann::json::array();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const double t = run.times[k];
    const std::vector<Eigen::Matrix3d> maps = quality ? interpolation.local_maps_at(t) : std::vector<Eigen::Matrix3d>{};
    nlohmann::json entry = output.record(static_cast<int>(k), frames[k], maps, quality);
    entry["t"] = t;
    if (energy) entry["energy"] = interpolation.energy_at(t, frames[k]);
    entries.push_back(std::move(entry));
  }
  output.close();
  return entries;
}

/// OUT/viewer.html: the frames on a time slider, with the inverted elements `measured` recorded.
void write_viewer(const Interpolate3Run& run, const global3::Mesh3& source, const std::vector<Eigen::Matrix3Xd>& frames,
                  const Frames3Output& measured, const fs::path& staging) {
  std::vector<std::string> labels;
  for (const double t : run.times) {
    std::ostringstream label;
    label << "t = " << std::setprecision(3) << t;
    labels.push_back(label.str());
  }
  const std::string title = fs::path(run.source).filename().string() + " -> " +
                            fs::path(run.target).filename().string() + " (" +
                            global::to_string(run.request.options.homotopy) + ", E^F)";
  write_viewer3_or_note(staging, title, source, frames, labels, measured);
}

}  // namespace

void refuse_planar_only_options(const CLI::App& command, const io::InterpolationRequest& request) {
  if (command.count("--energy") > 0 && request.options.energy != global::Energy::F)
    throw CommandFailed("--energy " + global::to_string(request.options.energy) +
                            ": 3D meshes take E^F only (E^R's closed form rests on the plane's complex numbers)",
                        usage_error);
  for (const char* option : {"--blend-weight", "--blend-weights", "--edge-direction", "--allow-flipped-target"})
    if (command.count(option) > 0)
      throw CommandFailed(std::string(option) + ": a 2D option, not available for 3D meshes", usage_error);
}

void run_interpolate3(const Interpolate3Run& run) {
  io::Poses3 pair;
  try {
    pair = io::read_poses3({run.source_mesh, run.target_mesh}, {run.source, run.target});
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  }
  if (pair.reoriented)
    std::cerr << "note: every tetrahedron was negatively oriented; all were reversed (same solids)\n";
  const global3::Mesh3& source = pair.poses[0];
  std::unique_ptr<global3::Interpolation3> interpolation;
  try {
    interpolation = std::make_unique<global3::Interpolation3>(source, pair.poses[1],
                                                              engine_options3(run.request, source.vertex_count()));
  } catch (const global::RefusedProblem& e) {
    throw CommandFailed(std::string("refused: ") + e.what(), 1);
  }
  const std::vector<Eigen::Index> folds = global3::target_folds(source, pair.poses[1]);
  if (!folds.empty())
    std::cerr << "note: the target folds " << folds.size() << " of " << source.element_count()
              << " triangles within the surface (metrics.json: target_folds); frames may invert at or beside them\n";
  StagedOutput staged(run.out);
  const std::vector<Eigen::Matrix3Xd> solved = interpolation->vertices_at(run.times);
  Frames3Output output(staged.staging(), source, run.times.size(), run.format, pair.reoriented);
  if (!folds.empty()) output.count_near_folds(global3::near_folds(source, folds));
  const nlohmann::json frames = write_frames(run, *interpolation, solved, output);
  if (run.figures) write_viewer(run, source, solved, output, staged.staging());
  const nlohmann::json document = {{"source", run.source},
                                   {"target", run.target},
                                   {"dimension", 3},
                                   {"vertices", source.vertex_count()},
                                   {"elements", source.element_count()},
                                   {"element_kind", source.corners() == 4 ? "tetrahedra" : "triangles"},
                                   {"reoriented", pair.reoriented},
                                   {"target_folds", folds},
                                   {"options", options3_json(run)},
                                   {"frames", frames}};
  std::ofstream(staged.staging() / "metrics.json") << document.dump(2) << "\n";
  commit_frames3(staged, run.out);
  std::cerr << "wrote " << frames_count(run.times.size()) << " to " << run.out << " ("
            << inverted_summary(frames, "the target's") << ")\n";
}

}  // namespace affinterp::cli
