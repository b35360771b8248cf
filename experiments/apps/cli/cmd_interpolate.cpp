// `affinterp interpolate`: global interpolation (Kaji §4) between a source and a target mesh, written as
// OBJ frames (or one frames.npy), a filmstrip (PNG + SVG), an animated GIF, an interactive viewer and
// per-frame metrics. The engine's options are bound straight into global::InterpolationOptions under the
// names of theory/global/options.hpp; the engine decides their defaults and rules.
#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/enum_option.hpp"
#include "experiments/apps/cli/interpolate3.hpp"
#include "experiments/inputs/constraint_spec.hpp"
#include "experiments/inputs/frame_metrics_json.hpp"
#include "experiments/inputs/frames_npy.hpp"
#include "experiments/inputs/interpolation_request.hpp"
#include "experiments/inputs/mesh3_file.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/support/progress.hpp"
#include "experiments/support/staged_output.hpp"
#include "plots/mesh_animation.hpp"
#include "plots/mesh_strip.hpp"
#include "plots/viewer.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/mesh_validation.hpp"
#include "theory/global/metrics.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <future>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

struct InterpolateOptions {
  std::string source, target, out;
  int frames = 30;
  io::InterpolationRequest request;  ///< the engine's options (its defaults) and the constraints' specifications
  std::string blend_weights;         ///< a file of w_i, one per triangle (empty: blend_weight for all)
  bool allow_flipped_target = false, figures = true;
  std::string time_range;            ///< T0:T1; empty: the engine's t_begin:t_end
  std::optional<std::string> times;  ///< --times T1,T2,...: exactly these frames (not with --frames, --time-range)
  std::string format = "obj";        ///< frame files: obj (one per frame) or npy (frames.npy, all of them)
  std::string metrics = "all";       ///< per-frame metrics in metrics.json: all, energy, quality or none
};

/// Frames drawn in the filmstrip: at most 8, evenly spread, first and last included.
constexpr std::size_t filmstrip_frames = 8;

/// T0:T1 as two reals; whether T0 <= T1 is the engine's rule (global::require_valid_options).
std::pair<double, double> parse_time_range(const std::string& text) {
  const auto colon = text.find(':');
  double t0 = 0, t1 = 0;
  std::istringstream a(text.substr(0, colon)), b(colon == std::string::npos ? "" : text.substr(colon + 1));
  if (colon == std::string::npos || !(a >> t0) || !(b >> t1) || !a.eof() || !b.eof())
    throw CommandFailed("--time-range '" + text + "': expected T0:T1 (e.g. 0:1 or -0.5:1.5)", usage_error);
  return {t0, t1};
}

/// The list of --times: finite reals separated by commas, in the order given (repeats allowed).
std::vector<double> parse_times(const std::string& text) {
  auto bad = [&] {
    return CommandFailed("--times '" + text + "': expected finite reals separated by commas (e.g. 0,0.1,0.5,1)",
                         usage_error);
  };
  std::vector<double> times;
  std::istringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    std::istringstream number(item);
    double t = 0;
    if (!(number >> t) || !(number >> std::ws).eof() || !std::isfinite(t)) throw bad();
    times.push_back(t);
  }
  if (times.empty() || text.back() == ',') throw bad();
  return times;
}

/// Sets the engine's time range from --times (their least and largest) or --time-range, and returns the
/// frames' times: --times as given, else --frames N evenly from t_begin to t_end.
std::vector<double> frame_times(const InterpolateOptions& o, global::InterpolationOptions& options) {
  if (o.times) {
    const std::vector<double> times = parse_times(*o.times);
    const auto [first, last] = std::minmax_element(times.begin(), times.end());
    options.t_begin = *first, options.t_end = *last;
    return times;
  }
  if (o.frames < 2) throw CommandFailed("--frames must be at least 2", usage_error);
  if (!o.time_range.empty()) std::tie(options.t_begin, options.t_end) = parse_time_range(o.time_range);
  std::vector<double> times;
  for (int k = 0; k < o.frames; ++k)
    times.push_back(options.t_begin + (options.t_end - options.t_begin) * k / (o.frames - 1));
  return times;
}

io::MeshPair read_pair(const InterpolateOptions& o) {
  io::MeshPair pair;
  try {
    pair = io::read_mesh_pair(o.source, o.target, {o.allow_flipped_target});
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  }
  if (pair.reoriented) std::cerr << "note: the triangles ran clockwise; all were reversed (same shape)\n";
  if (!pair.flipped_target_triangles.empty())
    std::cerr << "note: " << pair.flipped_target_triangles.size() << " target triangle(s) flipped (allowed)\n";
  return pair;
}

/// The engine's options and the frames' times; the engine itself checks the options (its error is printed).
std::pair<global::InterpolationOptions, std::vector<double>> engine_options(const InterpolateOptions& o,
                                                                            const io::MeshPair& pair) {
  io::InterpolationRequest request = o.request;
  const std::vector<double> times = frame_times(o, request.options);
  if (!o.blend_weights.empty()) {
    try {
      request.options.blend_weights = io::read_weights(o.blend_weights);
    } catch (const io::MeshFileError& e) {
      throw CommandFailed(e.what(), 1);
    }
  }
  try {
    return {io::interpolation_options(request, pair.source, pair.target), times};
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
}

/// metrics.json's "energy_parts": for a blend the E^F and E^R shares, for a symmetrised energy E(t) and
/// E^{-1}(1 − t), and the constraints C; each split plus C sums to "energy".
nlohmann::json energy_parts_json(const global::FrameEnergy& e, const global::InterpolationOptions& options) {
  nlohmann::json parts;
  if (options.energy == global::Energy::blend) parts["E_F"] = e.frobenius, parts["E_R"] = e.similarity;
  if (options.symmetric) parts["forward"] = e.forward, parts["backward"] = e.backward;
  parts["C"] = e.constraints;
  return parts;
}

std::string frame_name(int k) {
  std::ostringstream name;
  name << "frame_" << std::setw(4) << std::setfill('0') << k << ".obj";
  return name.str();
}

std::string time_label(double t) {
  std::ostringstream label;
  label << "t = " << std::setprecision(3) << t;
  return label.str();
}

/// What one run writes per frame: the frame files, metrics.json's "frames" entries, and what the figures draw.
class FrameRecorder {
 public:
  FrameRecorder(const InterpolateOptions& o, const io::MeshPair& pair, const global::Interpolation& interpolation,
                const global::InterpolationOptions& options, const fs::path& staging, std::size_t frame_count)
      : o_(o),
        pair_(pair),
        interpolation_(interpolation),
        options_(options),
        staging_(staging),
        energies_(o.figures || o.metrics == "all" || o.metrics == "energy"),
        quality_(o.figures || o.metrics == "all" || o.metrics == "quality"),
        frame_(pair.source) {
    if (pair.reoriented) global::reverse_orientation(frame_);  // frames keep the files' face list
    if (o.format == "npy") npy_.emplace(staging / "frames.npy", frame_count, pair.source.vertex_count());
    const std::string name = "E^" + global::to_string(options.energy) + (options.symmetric ? " symmetrised" : "");
    viewer_.energy = {{name, {}}};  // then the parts, as `view` reads them
  }

  void record(int k, double t, Eigen::Matrix2Xd vertices) {
    frame_.vertices = std::move(vertices);
    if (npy_)
      npy_->append(frame_.vertices);
    else
      io::write_obj(frame_, staging_ / frame_name(k));
    nlohmann::json entry = {{"index", k}, {"t", t}, {"file", npy_ ? "frames.npy" : frame_name(k)}};
    if (energies_) record_energy(k, t, entry);
    if (quality_) {
      const global::FrameMetrics metrics = global::frame_metrics(pair_.source, frame_.vertices);
      entry.update(io::metrics_json(metrics));
      if (o_.figures) viewer_.metrics.push_back(metrics);
    }
    frames_.push_back(std::move(entry));
    if (o_.figures) viewer_.times.push_back(t), viewer_.frames.push_back(frame_.vertices);
  }

  void close() {
    if (npy_) npy_->close();
  }

  const nlohmann::json& frames() const { return frames_; }
  plots::ViewerRun& viewer_run() { return viewer_; }
  bool has_quality() const { return quality_; }

 private:
  void record_energy(int k, double t, nlohmann::json& entry) {
    const global::FrameEnergy energy = interpolation_.energy_at(t, frame_.vertices);
    entry["energy"] = io::finite_or_null(energy.total);
    std::vector<plots::FrameSeries>& series = viewer_.energy;
    series[0].values.push_back(energy.total);
    if (options_.energy != global::Energy::blend && !options_.symmetric) return;
    entry["energy_parts"] = energy_parts_json(energy, options_);
    if (k == 0)
      for (const auto& [name, value] : entry["energy_parts"].items()) series.push_back({name, {}});
    for (std::size_t s = 1; s < series.size(); ++s)
      series[s].values.push_back(entry["energy_parts"][series[s].name].get<double>());
  }

  const InterpolateOptions& o_;
  const io::MeshPair& pair_;
  const global::Interpolation& interpolation_;
  const global::InterpolationOptions& options_;
  fs::path staging_;
  bool energies_, quality_;
  global::Mesh frame_;
  std::optional<io::NpyFrameWriter> npy_;
  nlohmann::json frames_ = nlohmann::json::array();
  plots::ViewerRun viewer_;
};

/// Solves the frames at `times` in batches of two per hardware thread (vertices_at(times) solves a batch in
/// parallel, a worker two at a time where the sparse back-end factorises two in one pass), the next batch
/// solved while this thread hands the last one to `frame_done(k, t, vertices)`.
template <class FrameDone>
void solve_in_batches(const global::Interpolation& interpolation, const std::vector<double>& times,
                      FrameDone frame_done) {
  const std::size_t batch = 2 * std::max(1u, std::thread::hardware_concurrency());
  auto solve = [&](std::size_t first) {
    const std::size_t last = std::min(times.size(), first + batch);
    return interpolation.vertices_at(std::vector<double>(times.begin() + static_cast<std::ptrdiff_t>(first),
                                                         times.begin() + static_cast<std::ptrdiff_t>(last)));
  };
  std::future<std::vector<Eigen::Matrix2Xd>> next = std::async(std::launch::async, solve, 0);
  for (std::size_t first = 0; first < times.size(); first += batch) {
    std::vector<Eigen::Matrix2Xd> solved = next.get();
    if (first + batch < times.size()) next = std::async(std::launch::async, solve, first + batch);
    for (std::size_t j = 0; j < solved.size(); ++j)
      frame_done(static_cast<int>(first + j), times[first + j], std::move(solved[j]));
  }
}

/// The filmstrip (at most filmstrip_frames, evenly spread), the animated GIF and the viewer, into `folder`.
void draw_figures(const fs::path& folder, const global::Mesh& source, const plots::ViewerRun& run,
                  std::optional<Progress>& progress) {
  std::vector<plots::MeshFrame> drawn, strip;
  for (std::size_t k = 0; k < run.frames.size(); ++k) drawn.push_back({run.frames[k], time_label(run.times[k])});
  const std::size_t n = drawn.size(), shown = std::min(n, filmstrip_frames);
  for (std::size_t j = 0; j < shown; ++j)
    strip.push_back(shown == 1 ? drawn[0] : drawn[(2 * j * (n - 1) + shown - 1) / (2 * (shown - 1))]);
  plots::draw_filmstrip(folder / "filmstrip", source.triangles, strip, run.title);
  if (progress) progress->advance();
  plots::write_animation_gif(folder / "animation.gif", source.triangles, drawn);
  if (progress) progress->advance();
  plots::write_viewer(folder / "viewer.html", run.title, {run});
  if (progress) progress->advance();
}

/// metrics.json: the input, the options under the names the CLI and Python use, and the frames.
nlohmann::json metrics_document(const InterpolateOptions& o, const io::MeshPair& pair,
                                const global::InterpolationOptions& options, const std::vector<double>& times,
                                const nlohmann::json& frames) {
  nlohmann::json used = io::options_json(o.request, options);
  used["blend_weights"] = o.blend_weights.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.blend_weights);
  used["format"] = o.format, used["metrics"] = o.metrics;
  used["times"] = o.times ? nlohmann::json(times) : nlohmann::json(nullptr);
  nlohmann::json document = {{"source", o.source},
                             {"target", o.target},
                             {"vertices", pair.source.vertex_count()},
                             {"triangles", pair.source.triangle_count()},
                             {"reoriented", pair.reoriented},
                             {"flipped_target_triangles", pair.flipped_target_triangles},
                             {"options", used},
                             {"frames", frames}};
  if (o.figures) document["animation"] = "animation.gif", document["viewer"] = "viewer.html";
  return document;
}

/// Moves the staged files into OUT, first removing earlier frames that this run does not replace (a longer
/// run's, or the other format's), which would mix two runs.
void commit_output(StagedOutput& staged, const fs::path& out) {
  std::error_code ignored;
  if (fs::is_directory(out))
    for (const auto& entry : fs::directory_iterator(out))
      if ((entry.path().filename().string().starts_with("frame_") && entry.path().extension() == ".obj") ||
          entry.path().filename() == "frames.npy")
        fs::remove(entry.path(), ignored);
  staged.commit();
}

void run(const InterpolateOptions& o) {
  const io::MeshPair pair = read_pair(o);
  const auto [options, times] = engine_options(o, pair);
  std::unique_ptr<global::Interpolation> interpolation;
  try {
    interpolation = std::make_unique<global::Interpolation>(pair.source, pair.target, options);
  } catch (const global::RefusedProblem& e) {
    throw CommandFailed(std::string("refused: ") + e.what(), 1);
  }

  StagedOutput staged(o.out);
  FrameRecorder recorder(o, pair, *interpolation, options, staged.staging(), times.size());
  recorder.viewer_run().title = fs::path(o.source).filename().string() + " -> " +
                                fs::path(o.target).filename().string() + " (" + global::to_string(options.homotopy) +
                                ", E^" + global::to_string(options.energy) + ")";
  recorder.viewer_run().source = pair.source;
  const bool long_run = static_cast<double>(times.size()) * static_cast<double>(pair.source.triangle_count()) > 2e5;
  std::optional<Progress> progress;  // the frames, then the filmstrip, the GIF and the viewer
  if (long_run) progress.emplace("interpolate", times.size() + (o.figures ? 3 : 0));
  solve_in_batches(*interpolation, times, [&](int k, double t, Eigen::Matrix2Xd vertices) {
    recorder.record(k, t, std::move(vertices));
    if (progress) progress->advance();
  });
  recorder.close();
  if (o.figures) draw_figures(staged.staging(), pair.source, recorder.viewer_run(), progress);
  progress.reset();  // ends the progress line before any other message
  std::ofstream(staged.staging() / "metrics.json")
      << metrics_document(o, pair, options, times, recorder.frames()).dump(2) << "\n";
  commit_output(staged, o.out);

  std::cerr << "wrote " << frames_count(times.size()) << " to " << o.out;
  if (recorder.has_quality()) {
    int worst = 0;
    for (const auto& f : recorder.frames()) worst = std::max(worst, f["flipped_triangles"].get<int>());
    std::cerr << " (most flipped triangles in a frame: " << worst << ")";
  }
  std::cerr << "\n";
}

/// 3D meshes (a .mesh file, or some z != 0) go to the 3D engine (interpolate3.cpp) under the same options.
void run_any(const InterpolateOptions& o, const CLI::App& cmd) {
  Interpolate3Run run3;
  try {  // each file read at most once by the 3D reader: a 3D mesh goes on to the engine as read
    run3.source_mesh = io::read_if_3d(o.source);
    if (!run3.source_mesh) run3.target_mesh = io::read_if_3d(o.target);
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  }
  if (!run3.source_mesh && !run3.target_mesh) {
    if (cmd.count("--arap-iterations") > 0)
      throw CommandFailed("--arap-iterations: a 3D option; for 2D meshes --energy R is E^R itself", usage_error);
    return run(o);
  }
  refuse_planar_only_options(cmd, o.request);
  run3.source = o.source, run3.target = o.target, run3.out = o.out, run3.request = o.request;
  run3.times = frame_times(o, run3.request.options);
  run3.times_given = o.times.has_value();
  run3.format = o.format, run3.metrics = o.metrics, run3.figures = o.figures;
  run_interpolate3(run3);
}

constexpr const char* description =
    "Interpolate between two compatible 2D triangle meshes (Kaji et al. 2012, §3-4): writes OUT/frame_0000.obj ... "
    "(or OUT/frames.npy with --format npy), OUT/filmstrip.png/.svg, OUT/animation.gif, OUT/viewer.html "
    "(interactive; viewer.html#frame=K opens at frame K) and OUT/metrics.json (per frame: t, the minimised energy "
    "E_t of Kaji §4 with its parts for a blend or --symmetric, and distortion metrics). Vertex indices are 0-based "
    "(the order of the v lines). Meshes: triangles only (polygons refused), z = 0; when every source triangle runs "
    "clockwise all are reversed for the computation (frames keep the files' face list); mixed orientations, "
    "zero-area source triangles and flipped target triangles (unless allowed) are refused. On any error OUT keeps "
    "its earlier content. 3D meshes (some z != 0; surfaces as .obj/.off/.ply/.stl, tetrahedra as MEDIT .mesh) "
    "run the 3D engine with E^F: frames as OBJ (surfaces) or .mesh (tetrahedra) or frames.npy (frames, n, 3), "
    "metrics.json per frame: t, energy, volume or area ratios, distortion, inverted elements (and as "
    "inverted_near_folds those at or beside the triangles a surface target folds within the surface, listed as "
    "target_folds); 2D-only options are refused.";

/// The options the engine takes (global::InterpolationOptions), under its names, defaults and choices.
void add_engine_options(CLI::App& cmd, InterpolateOptions& o) {
  global::InterpolationOptions& engine = o.request.options;
  add_enum_option(cmd, "--homotopy", engine.homotopy, "Local homotopy A_i(t) (Kaji §3)");
  add_enum_option(cmd, "--energy", engine.energy, "Local error E_i (Kaji §4)");
  add_enum_option(cmd, "--rotation-branch", engine.rotation_branch, "Polar angles of the A_i");
  cmd.add_option("--blend-weight", engine.blend_weight, "w in w E^F + (1-w) E^R for --energy blend, in [0, 1]")
      ->capture_default_str();
  cmd.add_option("--blend-weights", o.blend_weights,
                 "File of per-triangle blend weights w_i in [0, 1], one per line (--energy blend)");
  cmd.add_flag("--area-weighted,!--no-area-weighted", engine.area_weighted,
               "Weight each E_i by its source triangle's area (--no-area-weighted: the plain sum)")
      ->default_str(engine.area_weighted ? "true" : "false");
  cmd.add_flag("--symmetric", engine.symmetric, "Symmetric energy E(t) + E^-1(1-t)")
      ->default_str(engine.symmetric ? "true" : "false");
  cmd.add_option("--arap-iterations", o.request.arap_iterations,
                 "3D: as-rigid-as-possible steps on each E^F frame (each element may turn its A_i(t): E^R with the "
                 "scale held at 1; each step a solve and a rotation fitted to each element); 2D has --energy R itself")
      ->capture_default_str();
}

/// The constraints C of Kaji §4, in constraint_spec.hpp's syntax.
void add_constraint_options(CLI::App& cmd, io::InterpolationRequest& request) {
  cmd.add_option("--pin", request.pins, "V[@C]: vertex V moves on the straight line p_V -> q_V (repeatable)");
  cmd.add_option("--locus", request.loci,
                 "V[@C]:x1,y1;x2,y2;...: vertex V follows the spline through the points at t = 0..1 (repeatable; "
                 "3D: x1,y1,z1;...)");
  cmd.add_option(
      "--edge-direction", request.edge_directions,
      "I:J[:homotopy|linear][@C]: edge v_I - v_J follows the local homotopy (default) or the straight path. "
      "With E^S, E^R or blend and no --pin/--locus/--edge-direction, one edge of the source triangle nearest "
      "the barycentre follows its local homotopy (fixes rotation and scale; listed in metrics.json)");
  cmd.add_option("--barycentre-locus", request.barycentre_locus,
                 "linear[@C] | none | x1,y1;x2,y2;...[@C]: the barycentre's path (linear: source to target; 3D: "
                 "x1,y1,z1;...)")
      ->capture_default_str();
}

std::string time_range_text(double t0, double t1) {
  std::ostringstream text;
  text << t0 << ':' << t1;
  return text.str();
}

/// Which frames, and what is written for them.
void add_output_options(CLI::App& cmd, InterpolateOptions& o) {
  const global::InterpolationOptions& engine = o.request.options;
  CLI::Option* frames =
      cmd.add_option("--frames", o.frames, "Number of frames N (t = T0 + k (T1-T0)/(N-1))")->capture_default_str();
  CLI::Option* time_range =
      cmd.add_option("--time-range", o.time_range,
                     "T0:T1 with T0 <= T1, the times of the first and last frame (extrapolation allowed)")
          ->default_str(time_range_text(engine.t_begin, engine.t_end));
  cmd.add_option("--times", o.times,
                 "T1,T2,...: write exactly these frames, in this order (any finite reals, extrapolation allowed; "
                 "instead of --frames and --time-range)")
      ->excludes(frames)
      ->excludes(time_range);
  cmd.add_flag("--allow-flipped-target", o.allow_flipped_target, "Accept target triangles flipped against the source");
  cmd.add_option("--format", o.format,
                 "Frame files: obj (OUT/frame_0000.obj ...) or npy (OUT/frames.npy, all frames as one float64 array "
                 "of shape (frames, vertices, 2): numpy.load; for large meshes)")
      ->check(CLI::IsMember({"obj", "npy"}))
      ->capture_default_str();
  cmd.add_flag("!--no-figures", o.figures, "Write only frames and metrics.json (no filmstrip, GIF or viewer)");
  cmd.add_option("--metrics", o.metrics,
                 "What metrics.json gives per frame besides t: all, energy (E_t and its parts), quality (flips, "
                 "area ratios, distortion) or none; with the figures drawn all are computed (the viewer shows "
                 "them). Each costs about as much as the frame's solve on large meshes")
      ->check(CLI::IsMember({"all", "energy", "quality", "none"}))
      ->capture_default_str();
}

}  // namespace

void add_interpolate_command(CLI::App& app) {
  auto o = std::make_shared<InterpolateOptions>();
  CLI::App* cmd = app.add_subcommand("interpolate", description);
  cmd->add_option("--source", o->source,
                  "Source mesh (2D: .obj, .off, .ply, .stl or .ts with z = 0; 3D: .obj, .off, .ply, .stl or .mesh)")
      ->required();
  cmd->add_option("--target", o->target, "Target mesh with the same triangles")->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  add_engine_options(*cmd, *o);
  add_constraint_options(*cmd, o->request);
  add_output_options(*cmd, *o);
  cmd->callback([o, cmd] { run_any(*o, *cmd); });
}

}  // namespace affinterp::cli
