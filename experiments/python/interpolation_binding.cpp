// affinterp.Interpolation: the global interpolation of Kaji §4 between two compatible meshes. Its keywords are
// the engine's options under the names of `affinterp interpolate` and metrics.json, their defaults read from
// global::InterpolationOptions{}, their rules the engine's; the request and the input checks are the CLI's
// (experiments/inputs/interpolation_request.hpp, mesh_pair.hpp), so that Python and the CLI give the same vertices.
#include "experiments/inputs/frame_metrics_json.hpp"
#include "experiments/inputs/interpolation_request.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"
#include "experiments/python/engine_errors.hpp"
#include "experiments/python/json_dict.hpp"
#include "experiments/python/space_binding.hpp"
#include "theory/global/metrics.hpp"

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace affinterp::python {

namespace {

/// The keywords of Interpolation(): the engine's options under the names the CLI and metrics.json use.
struct Keywords {
  std::string homotopy, energy, rotation_branch;
  double blend_weight;
  std::optional<std::vector<double>> blend_weights;
  bool area_weighted, symmetric;
  std::vector<py::object> pins;
  std::vector<std::string> loci, edge_directions;
  std::string barycentre_locus;
  std::pair<double, double> time_range;
  int arap_iterations;
};

/// The request the CLI would make for the same keywords (experiments/inputs/interpolation_request.hpp).
io::InterpolationRequest request_of(const Keywords& k) {
  io::InterpolationRequest request;
  global::InterpolationOptions& options = request.options;
  options.homotopy = global::parse_option<global::LocalHomotopy>(k.homotopy);
  options.energy = global::parse_option<global::Energy>(k.energy);
  options.rotation_branch = global::parse_option<global::RotationBranch>(k.rotation_branch);
  options.blend_weight = k.blend_weight;
  if (k.blend_weights)
    options.blend_weights =
        Eigen::Map<const Eigen::VectorXd>(k.blend_weights->data(), static_cast<Eigen::Index>(k.blend_weights->size()));
  options.area_weighted = k.area_weighted, options.symmetric = k.symmetric;
  std::tie(options.t_begin, options.t_end) = k.time_range;
  for (const py::object& pin : k.pins) request.pins.push_back(py::str(pin));
  request.loci = k.loci, request.edge_directions = k.edge_directions, request.barycentre_locus = k.barycentre_locus;
  if (k.arap_iterations != 0) value_error("arap_iterations: a 3D keyword; for 2D meshes energy='R' is E^R itself");
  return request;
}

/// The keywords of a 3D interpolation: ValueError naming the first one that has no 3D counterpart (E^F is the
/// only 3D energy; the engine's default energy is taken as E^F there).
SpaceKeywords space_keywords(const Keywords& k) {
  const global::InterpolationOptions defaults;
  if (k.energy != "F" && k.energy != global::to_string(defaults.energy))
    value_error("energy '" + k.energy + "': 3D meshes take E^F only (E^R's closed form rests on the plane)");
  const auto refuse = [](const char* keyword) {
    value_error(std::string(keyword) + ": a 2D keyword, not for 3D meshes");
  };
  if (k.blend_weight != defaults.blend_weight) refuse("blend_weight");
  if (k.blend_weights) refuse("blend_weights");
  if (!k.edge_directions.empty()) refuse("edge_directions");
  SpaceKeywords space{k.homotopy, k.rotation_branch,  k.area_weighted, k.symmetric, k.arap_iterations, {},
                      k.loci,     k.barycentre_locus, k.time_range};
  for (const py::object& pin : k.pins) space.pins.push_back(py::str(pin));
  return space;
}

class Interpolation {
 public:
  Interpolation(const py::object& V0, const py::object& V1, const py::object& F, const Keywords& keywords) {
    if (is_space_points(V0)) {
      space_ = std::make_unique<SpaceInterpolation>(V0, V1, F, space_keywords(keywords));
      return;
    }
    global::Mesh source{points(V0, "V0"), triangles(F, "F")}, target{points(V1, "V1"), source.triangles};
    io::MeshPair pair;
    try {
      pair = io::check_mesh_pair(std::move(source), std::move(target), "V0", "V1");
    } catch (const io::MeshFileError& e) {
      value_error(e.what());
    }
    try {
      engine_ = std::make_unique<global::Interpolation>(
          pair.source, pair.target, io::interpolation_options(request_of(keywords), pair.source, pair.target));
    } catch (const global::RefusedProblem& e) {
      value_error(std::string("refused: ") + e.what());
    } catch (const std::invalid_argument& e) {
      value_error(e.what());
    }
    vertex_count_ = pair.source.vertex_count();
    source_ = std::move(pair.source);
  }

  py::array_t<double> vertices_at(double t) const {
    if (space_) return space_->vertices_at(t);
    Eigen::Matrix2Xd v;
    {
      py::gil_scoped_release unlocked;
      v = frame(t);
    }
    return to_points(std::move(v));
  }

  py::array_t<double> frames(const py::object& times) const {
    if (space_) return space_->frames(times);
    const std::vector<double> ts = reals(times, "times");
    py::array_t<double> out(
        {static_cast<py::ssize_t>(ts.size()), static_cast<py::ssize_t>(vertex_count_), py::ssize_t{2}});
    double* data = out.mutable_data();
    {
      py::gil_scoped_release unlocked;
      fill_frames(ts, data);
    }
    return out;
  }

  double energy_at(double t) const {
    if (space_) return space_->energy_at(t);
    py::gil_scoped_release unlocked;
    return engine_->energy_at(t, frame(t)).total;
  }

  /// metrics.json's entry of the frame at t: t, energy and the quality numbers (io::metrics_json).
  py::object metrics_at(double t) const {
    if (space_) return space_->metrics_at(t);
    nlohmann::json entry;
    {
      py::gil_scoped_release unlocked;
      const Eigen::Matrix2Xd v = frame(t);
      entry = {{"t", t}, {"energy", io::finite_or_null(engine_->energy_at(t, v).total)}};
      entry.update(io::metrics_json(global::frame_metrics(source_, v)));
    }
    return dict_of(entry);
  }

  /// The rotations' logarithms on their branch: 2D θ_i (m,), 3D ω_i (m, 3).
  py::array_t<double> rotation_logs() const {
    if (space_) return space_->rotation_logs();
    const Eigen::VectorXd& theta = engine_->rotation_angles();
    return py::array_t<double>(theta.size(), theta.data());
  }

  py::tuple rotation_split() const {
    if (!space_) value_error("rotation_split: 3D meshes only (in the plane each triangle turns along exp(t theta_i))");
    return space_->rotation_split();
  }

 private:
  Eigen::Matrix2Xd frame(double t) const {
    return translated([&] { return engine_->vertices_at(t); });
  }

  /// The frames at `times` written into `out`, frame k at out + 2nk, computed in parallel by the engine's
  /// batch call (interpolation.hpp).
  void fill_frames(const std::vector<double>& times, double* out) const {
    const std::vector<Eigen::Matrix2Xd> frames = translated([&] { return engine_->vertices_at(times); });
    for (std::size_t k = 0; k < frames.size(); ++k)
      Eigen::Map<Eigen::Matrix2Xd>(out + 2 * vertex_count_ * static_cast<Eigen::Index>(k), 2, vertex_count_) =
          frames[k];
  }

  std::unique_ptr<global::Interpolation> engine_;
  global::Mesh source_;                        ///< as the engine reoriented it, for the metrics
  std::unique_ptr<SpaceInterpolation> space_;  ///< set instead of engine_ for 3D meshes
  Eigen::Index vertex_count_ = 0;
};

}  // namespace

/// The class's docstring: the parameters' choices and meanings from the engine's name tables.
std::string docstring() {
  std::string doc = R"(Global interpolation (Kaji et al. 2012, §4) between compatible meshes.

For each time t the vertices v_1(t) ... v_n(t) minimise the global error
    E_t = sum_i E_i(A_i(t), B_i(t)) + C(v(t)),
A_i(t) the local homotopy of triangle tau_i (§3) from I to the affine map A_i of tau_i (eq. 1), B_i(t)
the linear part of the interpolated map on tau_i, E_i the local error and C the constraints.

Parameters (the names, defaults and rules of `affinterp interpolate`, which are the engine's):
  V0, V1            (n, 2) float arrays: source vertices P and target vertices Q
  F                 (m, 3) integer array: the triangles, shared by P and Q (0-based)
)";
  const auto choices = [](auto values) {
    std::string text;
    for (const auto& named : values)
      text += "\n                      '" + std::string(named.name) + "': " + std::string(named.meaning);
    return text;
  };
  doc += "  homotopy          the local homotopy A_i(t) (§3):" +
         choices(global::OptionNames<global::LocalHomotopy>::values);
  doc += "\n  energy            the local error E_i (§4):" + choices(global::OptionNames<global::Energy>::values);
  doc += "\n  rotation_branch   the polar angles of the A_i:" +
         choices(global::OptionNames<global::RotationBranch>::values);
  doc += R"(
  blend_weight      w in w E^F + (1 - w) E^R, in [0, 1]
  blend_weights     (m,) array of per-triangle w_i in [0, 1] (instead of blend_weight)
  area_weighted     weigh each E_i by the area of its source triangle
  symmetric         E'(t) = E(t) + E^{-1}(1 - t)
  pins              vertices (int, or 'V@C' strings) that move on the straight line p_V -> q_V
  loci              'V[@C]:x1,y1;x2,y2;...' strings: vertex V follows the spline through the points
  edge_directions   'I:J[:homotopy|linear][@C]' strings: edge v_I - v_J follows the local homotopy or a line
  barycentre_locus  'linear[@C]', 'none' or 'x1,y1;...[@C]': the barycentre's path
  time_range        (t0, t1), t0 <= t1: the times vertices_at accepts (extrapolation beyond [0, 1] allowed)
With E^S, E^R or a blend and no pins, loci or edge directions, one edge fixes rotation and scale, as in the
CLI. With (n, 3) vertices and (m, 3) triangles or (m, 4) tetrahedra the 3D engine runs (E^F; homotopy,
rotation_branch, area_weighted, symmetric, pins, loci 'V[@C]:x,y,z;...', barycentre_locus 'linear[@C]', 'none' or
'x,y,z;...[@C]', time_range, and arap_iterations: as-rigid-as-possible steps on each frame, E^R with its scale
held at 1, each a solve and a rotation fitted to each element), frames are (n, 3),
and the 2D-only keywords raise ValueError. Bad input (shapes, NaN, degenerate or flipped triangles, unknown
names, ...) raises ValueError with the CLI's one-line message.)";
  return doc;
}

void bind_interpolation(py::module_& m) {
  const global::InterpolationOptions defaults;
  const io::InterpolationRequest request_defaults;
  py::class_<Interpolation>(m, "Interpolation", docstring().c_str())
      .def(py::init([](const py::object& V0, const py::object& V1, const py::object& F, std::string homotopy,
                       std::string energy, std::string rotation_branch, double blend_weight,
                       std::optional<std::vector<double>> blend_weights, bool area_weighted, bool symmetric,
                       std::vector<py::object> pins, std::vector<std::string> loci,
                       std::vector<std::string> edge_directions, std::string barycentre_locus,
                       std::pair<double, double> time_range, int arap_iterations) {
             return std::make_unique<Interpolation>(
                 V0, V1, F,
                 Keywords{std::move(homotopy), std::move(energy), std::move(rotation_branch), blend_weight,
                          std::move(blend_weights), area_weighted, symmetric, std::move(pins), std::move(loci),
                          std::move(edge_directions), std::move(barycentre_locus), time_range, arap_iterations});
           }),
           py::arg("V0"), py::arg("V1"), py::arg("F"), py::kw_only(),
           py::arg("homotopy") = global::to_string(defaults.homotopy),
           py::arg("energy") = global::to_string(defaults.energy),
           py::arg("rotation_branch") = global::to_string(defaults.rotation_branch),
           py::arg("blend_weight") = defaults.blend_weight, py::arg("blend_weights") = py::none(),
           py::arg("area_weighted") = defaults.area_weighted, py::arg("symmetric") = defaults.symmetric,
           py::arg("pins") = std::vector<py::object>{}, py::arg("loci") = std::vector<std::string>{},
           py::arg("edge_directions") = std::vector<std::string>{},
           py::arg("barycentre_locus") = request_defaults.barycentre_locus,
           py::arg("time_range") = std::pair<double, double>{defaults.t_begin, defaults.t_end},
           py::arg("arap_iterations") = request_defaults.arap_iterations)
      .def("vertices_at", &Interpolation::vertices_at, py::arg("t"),
           "v(t) as an (n, 2) array: the minimiser of E_t. ValueError outside t_range.")
      .def("frames", &Interpolation::frames, py::arg("times"),
           "v(t) at each of `times` as a (k, n, 2) array (frame k is vertices_at(times[k])).")
      .def("energy_at", &Interpolation::energy_at, py::arg("t"),
           "E_t (E'(t) when symmetric) at its minimiser v(t), as metrics.json's \"energy\"; in 3D with "
           "arap_iterations, the as-rigid-as-possible energy those steps lower, at the refined frame.")
      .def("metrics_at", &Interpolation::metrics_at, py::arg("t"),
           "The frame at t's entry of `affinterp interpolate`'s metrics.json as a dict: t, energy and the quality "
           "numbers (2D: flipped_triangles, min_det, max_det, max_distortion, mean_distortion, area_ratio; 3D: "
           "inverted_elements, min_ratio, max_ratio, max_distortion, mean_distortion, measure_ratio, and "
           "inverted_near_folds when a surface target folds triangles within the surface); None where not finite.")
      .def("rotation_logs", &Interpolation::rotation_logs,
           "Each element's rotation logarithm on the branch rotation_branch chose: in the plane the polar angle "
           "theta_i, shape (m,); in space the axis-angle vector omega_i, shape (m, 3).")
      .def("rotation_split", &Interpolation::rotation_split,
           "3D only: (carrier, remainder), each (m, 3): on the consistent branch each element turns along "
           "exp(t carrier_i) exp(t remainder_i), the carrier its neighbours' turns filled across full turns and "
           "smoothed, the remainder the principal logarithm of what is left (the principal branch: carrier = omega, "
           "remainder = 0). ValueError for 2D meshes.");
}

}  // namespace affinterp::python
