// `affinterp interpolate`: global interpolation (Kaji §4) between a source and a target mesh, written as
// OBJ frames, a filmstrip (PNG + SVG), an animated GIF, an interactive viewer and per-frame metrics.
#include "experiments/apps/cli/command.hpp"
#include "experiments/inputs/constraint_spec.hpp"
#include "experiments/inputs/frames_npy.hpp"
#include "experiments/inputs/interpolation_request.hpp"
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

/// The engine's defaults (theory/global/options.hpp decides them; the options below only spell them).
const global::InterpolationOptions engine_defaults{};

std::string default_time_range() {
  std::ostringstream range;
  range << engine_defaults.t_begin << ':' << engine_defaults.t_end;
  return range.str();
}

struct InterpolateOptions {
  std::string source, target, out;
  int frames = 30;
  io::InterpolationRequest engine;  ///< the engine's options and their defaults, shared with the Python module
  std::string weights_file;
  bool allow_flipped_target = false, figures = true;
  std::string time_range = default_time_range();
  std::optional<std::string> times;  ///< --times T1,T2,...: exactly these frames (not with --frames, --time-range)
  std::string format = "obj";        ///< frame files: obj (one per frame) or npy (frames.npy, all of them)
  std::string metrics = "all";       ///< per-frame metrics in metrics.json: all, energy, quality or none
};

/// Frames drawn in the filmstrip: at most 8, evenly spread, first and last included.
constexpr std::size_t filmstrip_frames = 8;

std::pair<double, double> parse_time_range(const std::string& text) {
  const auto colon = text.find(':');
  double t0 = 0, t1 = 0;
  std::istringstream a(text.substr(0, colon)), b(colon == std::string::npos ? "" : text.substr(colon + 1));
  if (colon == std::string::npos || !(a >> t0) || !(b >> t1) || !a.eof() || !b.eof() || !std::isfinite(t0) ||
      !std::isfinite(t1) || t0 >= t1)
    throw CommandFailed("--time-range '" + text + "': expected T0:T1 with T0 < T1 (e.g. 0:1 or -0.5:1.5)", usage_error);
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

/// The frames' times: --times as given, else --frames N evenly over --time-range.
std::vector<double> frame_times(const InterpolateOptions& o) {
  if (o.times) return parse_times(*o.times);
  if (o.frames < 2) throw CommandFailed("--frames must be at least 2", usage_error);
  const auto [t0, t1] = parse_time_range(o.time_range);
  std::vector<double> times;
  for (int k = 0; k < o.frames; ++k) times.push_back(t0 + (t1 - t0) * k / (o.frames - 1));
  return times;
}

global::InterpolationOptions engine_options(const InterpolateOptions& o, const io::MeshPair& pair,
                                            const std::vector<double>& times) {
  io::InterpolationRequest request = o.engine;
  if (!o.weights_file.empty()) {
    try {
      request.blend_weights = io::read_weights(o.weights_file);
    } catch (const io::MeshFileError& e) {
      throw CommandFailed(e.what(), 1);
    }
    if (request.blend_weights.size() != pair.source.triangle_count())
      throw CommandFailed(o.weights_file + ": " + std::to_string(request.blend_weights.size()) + " weights for " +
                              std::to_string(pair.source.triangle_count()) + " triangles (one w_i per line)",
                          1);
  }
  const auto [first, last] = std::minmax_element(times.begin(), times.end());
  request.t_begin = *first, request.t_end = *last;
  try {
    return io::interpolation_options(request, pair.source, pair.target);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
}

/// A number for JSON: null when not finite (a singular B_i gives σ1/σ2 = +∞).
nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json metrics_json(const global::FrameMetrics& m) {
  return {{"flipped_triangles", m.flipped_triangles},
          {"min_det", finite_or_null(m.min_det)},
          {"max_det", finite_or_null(m.max_det)},
          {"max_distortion", finite_or_null(m.max_distortion)},
          {"mean_distortion", finite_or_null(m.mean_distortion)},
          {"area_ratio", finite_or_null(m.area_ratio)}};
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

bool energy_has_parts(const global::InterpolationOptions& options) {
  return options.energy == global::Energy::blend || options.symmetric;
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

void run(const InterpolateOptions& o) {
  const std::vector<double> times = frame_times(o);
  const int frame_count = static_cast<int>(times.size());
  io::MeshPair pair;
  try {
    pair = io::read_mesh_pair(o.source, o.target, {o.allow_flipped_target});
  } catch (const io::MeshFileError& e) {
    throw CommandFailed(e.what(), 1);
  }
  if (pair.reoriented) std::cerr << "note: the triangles ran clockwise; all were reversed (same shape)\n";
  if (!pair.flipped_target_triangles.empty())
    std::cerr << "note: " << pair.flipped_target_triangles.size() << " target triangle(s) flipped (allowed)\n";

  const global::InterpolationOptions options = engine_options(o, pair, times);
  const bool default_edge = options.constraints.edges.size() > o.engine.edges.size();
  std::unique_ptr<global::Interpolation> interpolation;
  try {
    interpolation = std::make_unique<global::Interpolation>(pair.source, pair.target, options);
  } catch (const global::RefusedProblem& e) {
    throw CommandFailed(std::string("refused: ") + e.what(), 1);
  }

  StagedOutput staged(o.out);
  nlohmann::json frames = nlohmann::json::array();
  const std::string title = fs::path(o.source).filename().string() + " -> " + fs::path(o.target).filename().string() +
                            " (" + o.engine.local + ", E^" + o.engine.energy + ")";
  plots::ViewerRun run{title, pair.source, {}, {}, {}, {}};
  const bool long_run = static_cast<double>(frame_count) * static_cast<double>(pair.source.triangle_count()) > 2e5;
  std::optional<Progress> progress;  // the frames, then the filmstrip, the GIF and the viewer
  if (long_run) progress.emplace("interpolate", static_cast<std::size_t>(frame_count) + (o.figures ? 3 : 0));
  const std::string energy_name = "E^" + o.engine.energy + (o.engine.symmetric ? " symmetrised" : "");
  std::vector<plots::FrameSeries> energy_series = {{energy_name, {}}};  // then the parts, as `view` reads them
  global::Mesh frame = pair.source;  // frames keep the files' face list, clockwise ones included
  if (pair.reoriented) global::reverse_orientation(frame);
  std::optional<io::NpyFrameWriter> npy;
  if (o.format == "npy")
    npy.emplace(staged.staging() / "frames.npy", static_cast<std::size_t>(frame_count), pair.source.vertex_count());
  // Frames in batches of two per hardware thread (vertices_at(times) solves them in parallel, a worker two at a
  // time where the sparse back-end factorises two in one pass), the next batch solved while this thread writes
  // the last one and computes the metrics asked for (all of them when the figures are drawn: the viewer shows them).
  const bool energies = o.figures || o.metrics == "all" || o.metrics == "energy",
             quality = o.figures || o.metrics == "all" || o.metrics == "quality";
  const std::size_t batch = 2 * std::max(1u, std::thread::hardware_concurrency());
  auto solve = [&](std::size_t first) {
    const std::size_t last = std::min(times.size(), first + batch);
    return interpolation->vertices_at(std::vector<double>(times.begin() + static_cast<std::ptrdiff_t>(first),
                                                          times.begin() + static_cast<std::ptrdiff_t>(last)));
  };
  std::future<std::vector<Eigen::Matrix2Xd>> next = std::async(std::launch::async, solve, 0);
  for (std::size_t first = 0; first < times.size(); first += batch) {
    std::vector<Eigen::Matrix2Xd> solved = next.get();
    if (first + batch < times.size()) next = std::async(std::launch::async, solve, first + batch);
    for (std::size_t j = 0; j < solved.size(); ++j) {
      const int k = static_cast<int>(first + j);
      const double t = times[first + j];
      frame.vertices = std::move(solved[j]);
      if (npy)
        npy->append(frame.vertices);
      else
        io::write_obj(frame, staged.staging() / frame_name(k));
      nlohmann::json entry = {{"index", k}, {"t", t}, {"file", npy ? "frames.npy" : frame_name(k)}};
      if (energies) {
        const global::FrameEnergy energy = interpolation->energy_at(t, frame.vertices);
        entry["energy"] = finite_or_null(energy.total);
        energy_series[0].values.push_back(energy.total);
        if (energy_has_parts(options)) {
          entry["energy_parts"] = energy_parts_json(energy, options);
          if (k == 0)
            for (const auto& [name, value] : entry["energy_parts"].items()) energy_series.push_back({name, {}});
          for (std::size_t s = 1; s < energy_series.size(); ++s)
            energy_series[s].values.push_back(entry["energy_parts"][energy_series[s].name].get<double>());
        }
      }
      if (quality) {
        const global::FrameMetrics metrics = global::frame_metrics(pair.source, frame.vertices);
        entry.update(metrics_json(metrics));
        if (o.figures) run.metrics.push_back(metrics);
      }
      frames.push_back(entry);
      if (o.figures) run.times.push_back(t), run.frames.push_back(frame.vertices);
      if (progress) progress->advance();
    }
  }
  if (npy) npy->close();

  nlohmann::json document = {{"source", o.source},
                             {"target", o.target},
                             {"vertices", pair.source.vertex_count()},
                             {"triangles", pair.source.triangle_count()},
                             {"reoriented", pair.reoriented},
                             {"flipped_target_triangles", pair.flipped_target_triangles},
                             {"options",
                              {{"local", o.engine.local},
                               {"energy", o.engine.energy},
                               {"rotation_branch", o.engine.rotation_branch},
                               {"area_weights", o.engine.area_weights},
                               {"symmetric", o.engine.symmetric},
                               {"blend_weight", o.engine.blend_weight},
                               {"weights_file", o.weights_file},
                               {"pins", o.engine.pins},
                               {"loci", o.engine.loci},
                               {"edge_directions", o.engine.edges},
                               {"barycentre_locus", o.engine.barycentre},
                               {"time_range", {options.t_begin, options.t_end}},
                               {"format", o.format},
                               {"metrics", o.metrics},
                               {"times", o.times ? nlohmann::json(times) : nlohmann::json(nullptr)}}},
                             {"frames", frames}};
  if (default_edge)
    document["options"]["default_edge_direction"] =
        std::to_string(options.constraints.edges.back().i) + ":" + std::to_string(options.constraints.edges.back().j);
  if (o.figures) {
    run.energy = std::move(energy_series);
    std::vector<plots::MeshFrame> drawn, strip;
    for (std::size_t k = 0; k < run.frames.size(); ++k) drawn.push_back({run.frames[k], time_label(run.times[k])});
    const std::size_t n = drawn.size(), shown = std::min(n, filmstrip_frames);
    for (std::size_t j = 0; j < shown; ++j)
      strip.push_back(shown == 1 ? drawn[0] : drawn[(2 * j * (n - 1) + shown - 1) / (2 * (shown - 1))]);
    plots::draw_filmstrip(staged.staging() / "filmstrip", pair.source.triangles, strip, title);
    if (progress) progress->advance();
    plots::write_animation_gif(staged.staging() / "animation.gif", pair.source.triangles, drawn);
    document["animation"] = "animation.gif";
    if (progress) progress->advance();
    plots::write_viewer(staged.staging() / "viewer.html", title, {run});
    document["viewer"] = "viewer.html";
    if (progress) progress->advance();
  }
  progress.reset();  // ends the progress line before any other message
  std::ofstream(staged.staging() / "metrics.json") << document.dump(2) << "\n";

  // Earlier frames beyond this run's count, or in the other format, would mix two runs: remove them, then
  // move the new files in.
  std::error_code ignored;
  if (fs::is_directory(o.out))
    for (const auto& entry : fs::directory_iterator(o.out))
      if ((entry.path().filename().string().starts_with("frame_") && entry.path().extension() == ".obj") ||
          entry.path().filename() == "frames.npy")
        fs::remove(entry.path(), ignored);
  staged.commit();
  std::cerr << "wrote " << frame_count << " frames to " << o.out;
  if (quality) {
    int worst = 0;
    for (const auto& f : frames) worst = std::max(worst, f["flipped_triangles"].get<int>());
    std::cerr << " (most flipped triangles in a frame: " << worst << ")";
  }
  std::cerr << "\n";
}

}  // namespace

void add_interpolate_command(CLI::App& app) {
  auto o = std::make_shared<InterpolateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "interpolate",
      "Interpolate between two compatible 2D triangle meshes (Kaji et al. 2012, §3-4): writes OUT/frame_0000.obj ... "
      "(or OUT/frames.npy with --format npy), "
      "OUT/filmstrip.png/.svg, OUT/animation.gif, OUT/viewer.html (interactive; viewer.html#frame=K opens at frame K) "
      "and "
      "OUT/metrics.json (per frame: t, the minimised energy E_t of Kaji §4 with its parts for a blend or --symmetric, "
      "and distortion metrics). Vertex indices are 0-based "
      "(the order of the v lines). Meshes: triangles only (polygons refused), z = 0; when every source triangle runs "
      "clockwise all are reversed for the computation (frames keep the files' face list); mixed orientations, "
      "zero-area "
      "source triangles and flipped target triangles (unless allowed) are refused. On any error OUT keeps its earlier "
      "content.");
  cmd->add_option("--source", o->source, "Source mesh (.obj, .off, .ply, .stl or .ts; z must be 0)")->required();
  cmd->add_option("--target", o->target, "Target mesh with the same triangles")->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  CLI::Option* frames =
      cmd->add_option("--frames", o->frames, "Number of frames N (t = T0 + k (T1-T0)/(N-1))")->capture_default_str();
  cmd->add_option("--local", o->engine.local, "Local homotopy A_i(t): exp (R^t S^t, eq. 3), polar (eq. 2), linear, svd")
      ->check(CLI::IsMember({"exp", "polar", "linear", "svd"}))
      ->capture_default_str();
  cmd->add_option("--energy", o->engine.energy,
                  "Local error E_i: F (Frobenius), S (similarity of points), R (eq. 4), blend")
      ->check(CLI::IsMember({"F", "S", "R", "blend"}))
      ->capture_default_str();
  cmd->add_option("--rotation-branch", o->engine.rotation_branch,
                  "Polar angles: consistent (chosen across neighbours, may exceed pi) or principal (-pi, pi]")
      ->check(CLI::IsMember({"consistent", "principal"}))
      ->capture_default_str();
  cmd->add_option("--blend-weight", o->engine.blend_weight, "w in w E^F + (1-w) E^R for --energy blend")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--weights", o->weights_file,
                  "File of per-triangle blend weights w_i, one per line (--energy blend)");
  cmd->add_flag("--area-weights,!--no-area-weights", o->engine.area_weights,
                "Weight each E_i by its source triangle's area (default; --no-area-weights: plain sum)");
  cmd->add_flag("--symmetric", o->engine.symmetric, "Symmetric energy E(t) + E^-1(1-t)");
  cmd->add_option("--pin", o->engine.pins, "V[@C]: vertex V moves on the straight line p_V -> q_V (repeatable)");
  cmd->add_option("--locus", o->engine.loci,
                  "V[@C]:x1,y1;x2,y2;...: vertex V follows the spline through the points at t = 0..1 (repeatable)");
  cmd->add_option(
      "--edge-direction", o->engine.edges,
      "I:J[:homotopy|linear][@C]: edge v_I - v_J follows the local homotopy (default) or the straight path. "
      "With E^S, E^R or blend and no --pin/--locus/--edge-direction, one edge of the source triangle nearest "
      "the barycentre follows its local homotopy (fixes rotation and scale; listed in metrics.json)");
  cmd->add_option("--barycentre-locus", o->engine.barycentre,
                  "linear[@C] | none | x1,y1;x2,y2;...[@C]: the barycentre's path (linear: source to target)")
      ->capture_default_str();
  CLI::Option* time_range = cmd->add_option("--time-range", o->time_range,
                                            "T0:T1, the times of the first and last frame (extrapolation allowed)")
                                ->capture_default_str();
  cmd->add_option("--times", o->times,
                  "T1,T2,...: write exactly these frames, in this order (any finite reals, extrapolation allowed; "
                  "instead of --frames and --time-range)")
      ->excludes(frames)
      ->excludes(time_range);
  cmd->add_flag("--allow-flipped-target", o->allow_flipped_target,
                "Accept target triangles flipped against the source");
  cmd->add_option("--format", o->format,
                  "Frame files: obj (OUT/frame_0000.obj ...) or npy (OUT/frames.npy, all frames as one float64 array "
                  "of shape (frames, vertices, 2): numpy.load; for large meshes)")
      ->check(CLI::IsMember({"obj", "npy"}))
      ->capture_default_str();
  cmd->add_flag("!--no-figures", o->figures, "Write only frames and metrics.json (no filmstrip, GIF or viewer)");
  cmd->add_option("--metrics", o->metrics,
                  "What metrics.json gives per frame besides t: all, energy (E_t and its parts), quality (flips, "
                  "area ratios, distortion) or none; with the figures drawn all are computed (the viewer shows "
                  "them). Each costs about as much as the frame's solve on large meshes")
      ->check(CLI::IsMember({"all", "energy", "quality", "none"}))
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace affinterp::cli
