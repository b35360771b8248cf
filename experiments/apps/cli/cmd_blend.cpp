// `affinterp blend`: N-way blends of K >= 2 compatible poses, in space or in the plane z = 0 (global3::Blend3, which
// keeps a flat blend flat: each element's rotation and stretch logarithms blended with the weights w, then E^F's
// solve, one factorisation for all weight vectors), or frames through key poses at given times
// (global3::Keyframes3). Writes the frames as `interpolate` does for 3D meshes, and metrics.json (per frame: the
// weights, t for keys, volume or area ratios, distortion, inverted elements).
#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/enum_option.hpp"
#include "experiments/apps/cli/frames3_output.hpp"
#include "experiments/inputs/mesh3_poses.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "theory/global3/keyframes3.hpp"
#include "theory/global3/target_folds3.hpp"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

struct BlendOptions {
  std::vector<std::string> poses, weights, keys;  ///< --poses FILE...; --weights W,W,... (repeatable); --keys FILE:T
  std::optional<std::string> times;               ///< --keys: the frames' times T,T,...
  int frames = 11;                                ///< --keys without --times: evenly from the first key to the last
  global3::Blend3Options engine;
  std::string out, format = "obj", metrics = "all";
  bool figures = true;  ///< OUT/viewer.html
};

/// A comma-separated list of finite reals; `option` names it in the error.
std::vector<double> parse_blend_reals(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::istringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    std::istringstream number(item);
    double x = 0;
    if (!(number >> x) || !(number >> std::ws).eof() || !std::isfinite(x))
      throw CommandFailed(option + " '" + text + "': expected finite reals separated by commas", usage_error);
    values.push_back(x);
  }
  if (values.empty() || text.back() == ',')
    throw CommandFailed(option + " '" + text + "': expected finite reals separated by commas", usage_error);
  return values;
}

io::Poses3 read_blend_poses(const std::vector<fs::path>& files) {
  try {
    io::Poses3 read = io::read_poses3(files);
    if (read.reoriented) std::cerr << "note: every tetrahedron was negatively oriented; all were reversed\n";
    return read;
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  }
}

/// One frame of the run: its weights, and its time for keyframes.
struct BlendFrame {
  Eigen::VectorXd weights;
  std::optional<double> t;
};

/// The viewer's title: the poses' file names, or the keys.
std::string blend_title(const BlendOptions& o) {
  std::string title = o.keys.empty() ? "blend of" : "keys";
  for (const std::string& input : o.keys.empty() ? o.poses : o.keys) title += " " + fs::path(input).filename().string();
  return title;
}

/// The slider's labels: "t = T" for keyframes, the weights for a blend.
std::vector<std::string> frame_labels(const std::vector<BlendFrame>& frames) {
  std::vector<std::string> labels;
  for (const BlendFrame& frame : frames) {
    std::ostringstream label;
    label << std::setprecision(3);
    if (frame.t) label << "t = " << *frame.t << ", ";
    label << "w = (";
    for (Eigen::Index k = 0; k < frame.weights.size(); ++k) label << (k ? ", " : "") << frame.weights[k];
    labels.push_back(label.str() + ")");
  }
  return labels;
}

/// Per pose, the triangles it folds within the surface against the first (target_folds3.hpp; none for the first),
/// with a note on standard error for each pose that folds any.
std::vector<std::vector<Eigen::Index>> pose_folds(const io::Poses3& read, const std::vector<std::string>& names) {
  const std::vector<std::vector<Eigen::Index>> folds = global3::pose_folds(read.poses);
  for (std::size_t k = 1; k < read.poses.size(); ++k) {
    if (!folds[k].empty())
      std::cerr << "note: " << names[k] << " folds " << folds[k].size() << " of " << read.poses[0].element_count()
                << " triangles within the surface against the first pose (metrics.json: pose_folds); frames may "
                   "invert at or beside them\n";
  }
  return folds;
}

/// Writes the frames of `blend` at `frames`' weights into OUT with metrics.json, after staging all of it; `read`
/// the poses (the first the rest pose).
void write_blend(const BlendOptions& o, const global3::Blend3& blend, const io::Poses3& read,
                 const std::vector<std::string>& names, const std::vector<BlendFrame>& frames,
                 nlohmann::json document) {
  const global3::Mesh3& rest = read.poses[0];
  const std::vector<std::vector<Eigen::Index>> folds = pose_folds(read, names);
  std::vector<Eigen::VectorXd> weights;
  for (const BlendFrame& frame : frames) weights.push_back(frame.weights);
  const std::vector<Eigen::Matrix3Xd> solved = blend.vertices_at(weights);
  StagedOutput staged(o.out);
  Frames3Output output(staged.staging(), rest, frames.size(), o.format, read.reoriented);
  if (std::vector<unsigned char> near = global3::near_pose_folds(read.poses, folds); !near.empty())
    output.count_near_folds(std::move(near));
  const bool quality = o.metrics == "all";
  nlohmann::json entries = nlohmann::json::array();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto maps = quality ? blend.local_maps_at(weights[k]) : std::vector<Eigen::Matrix3d>{};
    nlohmann::json entry = output.record(static_cast<int>(k), solved[k], maps, quality);
    entry["weights"] = std::vector<double>(weights[k].data(), weights[k].data() + weights[k].size());
    if (frames[k].t) entry["t"] = *frames[k].t;
    entries.push_back(std::move(entry));
  }
  output.close();
  if (o.figures) write_viewer3_or_note(staged.staging(), blend_title(o), rest, solved, frame_labels(frames), output);
  document["vertices"] = rest.vertex_count(), document["elements"] = rest.element_count();
  document["element_kind"] = rest.corners() == 4 ? "tetrahedra" : "triangles";
  document["pose_folds"] = folds;
  document["options"] = {{"rotation_branch", global::to_string(o.engine.rotation_branch)},
                         {"area_weighted", o.engine.area_weighted},
                         {"allow_extrapolation", o.engine.allow_extrapolation},
                         {"arap_iterations", o.engine.arap_iterations},
                         {"format", o.format},
                         {"metrics", o.metrics}};
  document["frames"] = entries;
  std::ofstream(staged.staging() / "metrics.json") << document.dump(2) << "\n";
  commit_frames3(staged, o.out);
  std::cerr << "wrote " << frames_count(frames.size()) << " to " << o.out << " ("
            << inverted_summary(entries, "the poses'") << ")\n";
}

/// --poses with --weights: one frame per weight vector, all checked before anything is written.
void run_weights(const BlendOptions& o) {
  if (o.weights.empty()) throw CommandFailed("--poses needs at least one --weights vector", usage_error);
  const io::Poses3 read = read_blend_poses({o.poses.begin(), o.poses.end()});
  std::vector<BlendFrame> frames;
  for (const std::string& text : o.weights) {
    const std::vector<double> w = parse_blend_reals(text, "--weights");
    frames.push_back({Eigen::Map<const Eigen::VectorXd>(w.data(), static_cast<Eigen::Index>(w.size())), {}});
  }
  try {
    const global3::Blend3 blend(read.poses, o.engine);
    for (const BlendFrame& frame : frames) blend.require_valid_weights(frame.weights);
    write_blend(o, blend, read, o.poses, frames, {{"poses", o.poses}});
  } catch (const global::RefusedProblem& e) {
    throw CommandFailed(std::string("refused: ") + e.what(), 1);
  }
}

/// FILE:T split at the last colon.
std::pair<std::string, double> parse_key(const std::string& key) {
  const auto colon = key.rfind(':');
  if (colon == std::string::npos || colon == 0)
    throw CommandFailed("--keys '" + key + "': expected FILE:TIME", usage_error);
  return {key.substr(0, colon), parse_blend_reals(key.substr(colon + 1), "--keys")[0]};
}

/// The frames' times: --times as given, else --frames evenly from the first key time to the last.
std::vector<double> key_frame_times(const BlendOptions& o, double first, double last) {
  if (o.times) return parse_blend_reals(*o.times, "--times");
  if (o.frames < 2) throw CommandFailed("--frames must be at least 2", usage_error);
  std::vector<double> times;
  for (int k = 0; k < o.frames; ++k) times.push_back(first + (last - first) * k / (o.frames - 1));
  return times;
}

/// --keys: frames through the key poses at their times (C0 at the keys: keyframes3.hpp).
void run_keys(const BlendOptions& o) {
  std::vector<fs::path> files;
  std::vector<std::string> names;
  std::vector<double> key_times;
  for (const std::string& key : o.keys) {
    auto [file, t] = parse_key(key);
    files.push_back(file), names.push_back(file), key_times.push_back(t);
  }
  const io::Poses3 read = read_blend_poses(files);
  try {
    const global3::Keyframes3 keyframes(read.poses, key_times, o.engine);
    std::vector<BlendFrame> frames;
    for (const double t : key_frame_times(o, key_times.front(), key_times.back())) {
      if (!(t >= key_times.front() && t <= key_times.back()))
        throw CommandFailed("--times: " + std::to_string(t) + " lies outside the key times", usage_error);
      frames.push_back({keyframes.weights_at(t), t});
    }
    write_blend(o, keyframes.blend(), read, names, frames, {{"keys", o.keys}});
  } catch (const global::RefusedProblem& e) {
    throw CommandFailed(std::string("refused: ") + e.what(), 1);
  }
}

constexpr const char* blend_description =
    "Blend K >= 2 compatible poses (surfaces .obj/.off/.ply/.stl or MEDIT .mesh tetrahedra; 2D meshes, z = 0, blend "
    "in the plane, two of them at weights 1-t,t giving interpolate's --energy F frames): with --poses A B C "
    "--weights 0.2,0.5,0.3 one frame per --weights vector, each element's map exp(sum_k w_k log R_k) "
    "exp(sum_k w_k log S_k) from the first pose (with --rotation-branch consistent, the default, each log R_k turned "
    "along its smoothed carrier, then its remainder), then the E^F solve (weights off the simplex only with "
    "--allow-extrapolation); with --keys A:0 B:0.5 C:1 frames through the poses at those times (--times or "
    "--frames), each segment the blend of its two keys (continuous at the keys). Writes OUT/frame_0000.obj (.mesh "
    "for tetrahedra) ... or OUT/frames.npy (frames, n, 3), OUT/metrics.json (per frame the weights and quality "
    "metrics, inverted elements among them, and as inverted_near_folds those at or beside the triangles a surface pose "
    "folds within the surface against the first, listed per pose as pose_folds) and OUT/viewer.html (orbit, a slider "
    "over the frames, faces coloured by distortion or by the inverted elements metrics.json counts). On any error OUT "
    "keeps its earlier content.";

void add_blend_inputs(CLI::App& cmd, BlendOptions& o) {
  CLI::Option* poses = cmd.add_option("--poses", o.poses, "The poses (the first is the rest mesh)");
  cmd.add_option("--weights", o.weights, "W1,...,WK: one frame with these weights (repeatable)")->needs(poses);
  CLI::Option* keys = cmd.add_option("--keys", o.keys, "FILE:T ...: key poses at increasing times")->excludes(poses);
  CLI::Option* times = cmd.add_option("--times", o.times, "T1,T2,...: the frames' times (with --keys)")->needs(keys);
  cmd.add_option("--frames", o.frames, "Frames evenly from the first key to the last (with --keys)")
      ->needs(keys)
      ->excludes(times)
      ->capture_default_str();
  cmd.add_flag("--allow-extrapolation", o.engine.allow_extrapolation, "Accept weights off the simplex");
}

void add_blend_outputs(CLI::App& cmd, BlendOptions& o) {
  add_enum_option(cmd, "--rotation-branch", o.engine.rotation_branch, "Rotation logarithms of the element maps");
  cmd.add_flag("--area-weighted,!--no-area-weighted", o.engine.area_weighted,
               "Weight each element by its rest area or volume (--no-area-weighted: the plain sum)")
      ->default_str("true");
  cmd.add_option("--arap-iterations", o.engine.arap_iterations,
                 "As-rigid-as-possible steps on each frame, as interpolate's --arap-iterations")
      ->capture_default_str();
  cmd.add_option("--out", o.out, "Output folder")->required();
  cmd.add_option("--format", o.format, "Frame files: obj (.mesh for tetrahedra) or npy (frames, vertices, 3)")
      ->check(CLI::IsMember({"obj", "npy"}))
      ->capture_default_str();
  cmd.add_option("--metrics", o.metrics, "Per-frame quality metrics in metrics.json: all or none")
      ->check(CLI::IsMember({"all", "none"}))
      ->capture_default_str();
  cmd.add_flag("!--no-figures", o.figures, "Write only frames and metrics.json (no viewer.html)");
}

}  // namespace

void add_blend_command(CLI::App& app) {
  auto o = std::make_shared<BlendOptions>();
  CLI::App* cmd = app.add_subcommand("blend", blend_description);
  add_blend_inputs(*cmd, *o);
  add_blend_outputs(*cmd, *o);
  cmd->callback([o] {
    if (o->keys.empty() && o->poses.empty()) throw CommandFailed("blend needs --poses or --keys", usage_error);
    if (o->keys.empty())
      run_weights(*o);
    else
      run_keys(*o);
  });
}

}  // namespace affinterp::cli
