// affinterp.Interpolation: the global interpolation of Kaji §4 between two compatible meshes, with the
// defaults of `affinterp interpolate` (experiments/inputs/interpolation_request.hpp) and its input checks
// (experiments/inputs/mesh_pair.hpp), so that Python and the CLI give the same vertices.
#include "experiments/inputs/interpolation_request.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/mesh_pair.hpp"
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"

#include <pybind11/stl.h>

#include <memory>

namespace affinterp::python {

namespace {

class Interpolation {
 public:
  Interpolation(const py::object& V0, const py::object& V1, const py::object& F, const std::string& homotopy,
                const std::string& energy, bool symmetric, bool area_weighted, const std::vector<py::object>& pins,
                std::pair<double, double> t_range, const std::string& rotation_branch, double blend_weight) {
    global::Mesh source{points(V0, "V0"), triangles(F, "F")}, target{points(V1, "V1"), source.triangles};
    io::MeshPair pair;
    try {
      pair = io::check_mesh_pair(std::move(source), std::move(target), "V0", "V1");
    } catch (const io::MeshFileError& e) {
      value_error(e.what());
    }
    io::InterpolationRequest request;
    request.local = homotopy, request.energy = energy, request.symmetric = symmetric;
    request.area_weights = area_weighted, request.rotation_branch = rotation_branch;
    request.blend_weight = blend_weight;
    for (const py::object& pin : pins) request.pins.push_back(py::str(pin));
    request.t_begin = t_range.first, request.t_end = t_range.second;
    if (!(request.t_begin <= request.t_end) || !std::isfinite(request.t_begin) || !std::isfinite(request.t_end))
      value_error("t_range: expected finite (t0, t1) with t0 <= t1");
    try {
      engine_ = std::make_unique<global::Interpolation>(pair.source, pair.target,
                                                        io::interpolation_options(request, pair.source, pair.target));
    } catch (const global::RefusedProblem& e) {
      value_error(std::string("refused: ") + e.what());
    } catch (const std::invalid_argument& e) {
      value_error(e.what());
    }
    vertex_count_ = pair.source.vertex_count();
  }

  py::array_t<double> vertices_at(double t) const {
    Eigen::Matrix2Xd v;
    {
      py::gil_scoped_release unlocked;
      v = frame(t);
    }
    return to_points(std::move(v));
  }

  py::array_t<double> frames(const py::object& times) const {
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
    py::gil_scoped_release unlocked;
    return engine_->energy_at(t, frame(t)).total;
  }

 private:
  /// The engine's answer to `call`, with its errors as ValueErrors (an error escapes the released GIL as a
  /// C++ exception and is translated once it is held again).
  template <class Call>
  auto translated(Call call) const {
    try {
      return call();
    } catch (const std::out_of_range& e) {
      throw std::invalid_argument(e.what());
    } catch (const global::RefusedProblem& e) {
      throw std::invalid_argument(std::string("refused: ") + e.what());
    }
  }

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
  Eigen::Index vertex_count_ = 0;
};

}  // namespace

void bind_interpolation(py::module_& m) {
  py::class_<Interpolation>(m, "Interpolation",
                            R"(Global interpolation (Kaji et al. 2012, §4) between compatible meshes.

For each time t the vertices v_1(t) ... v_n(t) minimise the global error
    E_t = sum_i E_i(A_i(t), B_i(t)) + C(v(t)),
A_i(t) the local homotopy of triangle tau_i (§3) from I to the affine map A_i of tau_i (eq. 1), B_i(t)
the linear part of the interpolated map on tau_i, E_i the local error and C the constraints.

Parameters (defaults as `affinterp interpolate`):
  V0, V1         (n, 2) float arrays: source vertices P and target vertices Q
  F              (m, 3) integer array: the triangles, shared by P and Q (0-based)
  homotopy       'exp' (A^E = R_{t theta} S^t, eq. 3), 'polar' (eq. 2), 'linear', 'svd'
  energy         'R' (E^R, eq. 4), 'F' (Frobenius), 'S' (similarity of points), 'blend'
  symmetric      E'(t) = E(t) + E^{-1}(1 - t)
  area_weighted  weigh each E_i by the area of its source triangle
  pins           vertices (int, or 'V@C' strings) that move on the straight line p_V -> q_V
  t_range        (t0, t1): the times vertices_at accepts (extrapolation beyond [0, 1] allowed)
  rotation_branch  'consistent' or 'principal'
  blend_weight   w in w E^F + (1 - w) E^R
With E^S, E^R or a blend and no pins, one edge fixes rotation and scale and the barycentre follows the
straight line, as in the CLI. Bad input (shapes, NaN, degenerate or flipped triangles, ...) raises
ValueError with the CLI's one-line message.)")
      .def(
          py::init<const py::object&, const py::object&, const py::object&, const std::string&, const std::string&,
                   bool, bool, const std::vector<py::object>&, std::pair<double, double>, const std::string&, double>(),
          py::arg("V0"), py::arg("V1"), py::arg("F"), py::kw_only(), py::arg("homotopy") = "exp",
          py::arg("energy") = "R", py::arg("symmetric") = false, py::arg("area_weighted") = true,
          py::arg("pins") = std::vector<py::object>{}, py::arg("t_range") = std::pair<double, double>{0.0, 1.0},
          py::arg("rotation_branch") = "consistent", py::arg("blend_weight") = 0.5)
      .def("vertices_at", &Interpolation::vertices_at, py::arg("t"),
           "v(t) as an (n, 2) array: the minimiser of E_t. ValueError outside t_range.")
      .def("frames", &Interpolation::frames, py::arg("times"),
           "v(t) at each of `times` as a (k, n, 2) array (frame k is vertices_at(times[k])).")
      .def("energy_at", &Interpolation::energy_at, py::arg("t"),
           "E_t (E'(t) when symmetric) at its minimiser v(t), as metrics.json's \"energy\".");
}

}  // namespace affinterp::python
