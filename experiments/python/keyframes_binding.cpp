// affinterp.Keyframes: frames through K poses at increasing key times (global3::Keyframes3: between keys k and
// k + 1 the blend of those two poses, continuous at the keys), in space or in the plane, as `affinterp blend --keys`
// makes them.
#include "experiments/python/bindings.hpp"
#include "experiments/python/engine_errors.hpp"
#include "experiments/python/space_binding.hpp"
#include "theory/global3/keyframes3.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

namespace affinterp::python {

namespace {

class Keyframes {
 public:
  Keyframes(const py::iterable& poses, const py::object& F, const py::object& times, const std::string& rotation_branch,
            bool area_weighted, int arap_iterations) {
    const std::vector<global3::Mesh3> meshes = pose_meshes(poses, F, planar_);
    const global3::Blend3Options options = blend_options(rotation_branch, area_weighted, arap_iterations);
    engine_ = translated([&] { return std::make_unique<global3::Keyframes3>(meshes, reals(times, "times"), options); });
    vertex_count_ = meshes[0].vertex_count();
  }

  /// A time gives its frame, (n, 3) or (n, 2); a sequence of times (frames, n, 3) or (frames, n, 2).
  py::array_t<double> vertices_at(const py::object& t) const {
    const bool one = py::isinstance<py::float_>(t) || py::isinstance<py::int_>(t);
    const std::vector<double> ts = reals(t, "t");
    std::vector<Eigen::Matrix3Xd> frames;
    {
      py::gil_scoped_release unlocked;
      frames = translated([&] { return engine_->vertices_at(ts); });
    }
    if (one) return frame_points(std::move(frames[0]), planar_);
    return stacked(frames, vertex_count_, planar_ ? 2 : 3);
  }

  py::array_t<double> weights_at(double t) const {
    const Eigen::VectorXd w = translated([&] { return engine_->weights_at(t); });
    return py::array_t<double>(w.size(), w.data());
  }

 private:
  std::unique_ptr<global3::Keyframes3> engine_;
  bool planar_ = false;
  Eigen::Index vertex_count_ = 0;
};

}  // namespace

void bind_keyframes(py::module_& m) {
  py::class_<Keyframes>(m, "Keyframes", R"(Frames through K >= 2 compatible poses at increasing key times, as
`affinterp blend --keys` makes them: between keys k and k + 1 the blend (affinterp.Blend) with weights (1 - s) on
pose k and s on pose k + 1, s = (t - t_k)/(t_{k+1} - t_k); pose 0 the rest mesh, one factorisation for all frames.
Continuous at the keys (each is its pose from either side); the velocity generally jumps there.

  poses            a sequence of K (n, 3) float arrays, or K (n, 2) ones for poses in the plane (frames (n, 2))
  F                (m, 3) triangles or (m, 4) tetrahedra (0-based), shared by the poses
  times            K strictly increasing finite key times
  rotation_branch  'consistent' or 'principal', as Blend's
  area_weighted    weigh each element by its rest area or volume
  arap_iterations  as-rigid-as-possible steps on each frame (as Interpolation's)
Bad input, and a time outside [times[0], times[-1]], raise ValueError with a one-line message.)")
      .def(py::init<const py::iterable&, const py::object&, const py::object&, const std::string&, bool, int>(),
           py::arg("poses"), py::arg("F"), py::arg("times"), py::kw_only(),
           py::arg("rotation_branch") = global::to_string(global3::Blend3Options{}.rotation_branch),
           py::arg("area_weighted") = true, py::arg("arap_iterations") = global3::Blend3Options{}.arap_iterations)
      .def("vertices_at", &Keyframes::vertices_at, py::arg("t"),
           "The frame at time t, (n, 3) (or (n, 2) in the plane); a sequence of times gives (frames, n, 3).")
      .def("weights_at", &Keyframes::weights_at, py::arg("t"),
           "The blend weights of time t, shape (K,): at most two adjacent entries are not zero.");
}

}  // namespace affinterp::python
