// `affinterp view`: runs of `affinterp interpolate` side by side in one interactive page on one time slider
// (plots/viewer.hpp), read back from their output folders: metrics.json, the frame OBJs and the source and
// target meshes metrics.json names.
#include "experiments/apps/cli/command.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/support/interrupt_cleanup.hpp"
#include "plots/viewer.hpp"
#include "theory/global/metrics.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <memory>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

struct ViewOptions {
  std::vector<std::string> runs;
  std::string out, title;
};

/// A mesh path as metrics.json records it (as given to interpolate): from here, else from the run folder.
fs::path recorded_mesh(const fs::path& run, const std::string& recorded) {
  const fs::path path(recorded);
  if (path.is_absolute() || fs::exists(path)) return path;
  return run / path;
}

double number_or_infinity(const nlohmann::json& x) {
  return x.is_null() ? std::numeric_limits<double>::infinity() : x.get<double>();
}

plots::ViewerRun read_run(const fs::path& folder) {
  const fs::path file = folder / "metrics.json";
  std::ifstream in(file);
  if (!in)
    throw CommandFailed(folder.string() + ": no metrics.json (not an output folder of affinterp interpolate)", 1);
  try {
    const nlohmann::json document = nlohmann::json::parse(in);
    const io::MeshPair pair = io::read_mesh_pair(recorded_mesh(folder, document.at("source").get<std::string>()),
                                                 recorded_mesh(folder, document.at("target").get<std::string>()),
                                                 {.allow_flipped_target = true});
    const auto& options = document.at("options");
    plots::ViewerRun run{
        folder.filename().string() + ": " + fs::path(document["source"].get<std::string>()).filename().string() +
            " -> " + fs::path(document["target"].get<std::string>()).filename().string() + " (" +
            options.at("homotopy").get<std::string>() + ", E^" + options.at("energy").get<std::string>() + ")",
        pair.source,
        {},
        {},
        {},
        {}};
    // the minimised energy of each frame, then its parts (energy_parts: E_F, E_R, forward, backward, C)
    const bool symmetric = options.value("symmetric", false);
    std::vector<plots::FrameSeries> energy = {
        {"E^" + options.at("energy").get<std::string>() + (symmetric ? " symmetrised" : ""), {}}};
    const nlohmann::json& first = document.at("frames").empty() ? nlohmann::json() : document["frames"][0];
    if (first.contains("energy_parts"))
      for (const auto& [name, value] : first["energy_parts"].items()) energy.push_back({name, {}});
    for (const auto& frame : document.at("frames")) {
      const global::Mesh mesh = io::read_mesh(folder / frame.at("file").get<std::string>());
      if (mesh.vertex_count() != pair.source.vertex_count())
        throw CommandFailed((folder / frame["file"].get<std::string>()).string() + ": " +
                                std::to_string(mesh.vertex_count()) + " vertices, the source " +
                                std::to_string(pair.source.vertex_count()),
                            1);
      run.times.push_back(frame.at("t").get<double>());
      run.frames.push_back(mesh.vertices);
      if (frame.contains("flipped_triangles"))
        run.metrics.push_back({frame["flipped_triangles"].get<Eigen::Index>(), number_or_infinity(frame.at("min_det")),
                               number_or_infinity(frame.at("max_det")), number_or_infinity(frame.at("max_distortion")),
                               number_or_infinity(frame.at("mean_distortion")),
                               number_or_infinity(frame.at("area_ratio"))});
      else  // a run with --metrics energy or none
        run.metrics.push_back(global::frame_metrics(pair.source, mesh.vertices));
      if (!frame.contains("energy")) continue;
      energy[0].values.push_back(number_or_infinity(frame["energy"]));
      for (std::size_t s = 1; s < energy.size(); ++s)
        energy[s].values.push_back(number_or_infinity(frame.at("energy_parts").at(energy[s].name)));
    }
    if (run.frames.empty()) throw CommandFailed(file.string() + ": no frames", 1);
    if (energy[0].values.size() == run.frames.size()) run.energy = std::move(energy);
    return run;
  } catch (const nlohmann::json::exception& e) {
    throw CommandFailed(file.string() + ": " + e.what(), 1);
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(folder.string() + ": " + e.what(), 1);
  }
}

void run(const ViewOptions& o) {
  std::vector<plots::ViewerRun> runs;
  for (const auto& folder : o.runs) runs.push_back(read_run(folder));
  std::string title = o.title;
  if (title.empty())
    for (std::size_t r = 0; r < o.runs.size(); ++r) title += (r ? " | " : "") + o.runs[r];
  // Written beside OUT first, so a failed or interrupted run leaves an earlier OUT as it was.
  const fs::path out(o.out), partial = out.string() + ".partial-" + std::to_string(getpid());
  RemovedOnInterrupt removed(partial);
  try {
    plots::write_viewer(partial, title, runs);
  } catch (const std::runtime_error& e) {
    fs::remove(partial);
    throw CommandFailed(e.what(), 1);
  }
  removed.settle([&] { fs::rename(partial, out); });
  std::cerr << "wrote " << o.out << " (" << runs.size() << " run" << (runs.size() > 1 ? "s" : "") << ")\n";
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Show runs of `affinterp interpolate` side by side on one time slider: writes one self-contained HTML page "
      "(open it in a browser; nothing is fetched; PAGE.html#frame=K opens at frame K). Each RUN is an output folder "
      "of interpolate: its metrics.json, frames and the source and target meshes it names.");
  cmd->add_option("runs", o->runs, "Output folders of affinterp interpolate (one or more)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--out", o->out, "The page to write, e.g. compare.html")->required();
  cmd->add_option("--title", o->title, "The page's heading (default: the folders' names)");
  cmd->callback([o] { run(*o); });
}

}  // namespace affinterp::cli
