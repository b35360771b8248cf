// affinterp.pair: compatible meshes from two outlines (experiments/inputs/compatible_pair.hpp), as
// `affinterp pair`.
#include "experiments/inputs/compatible_pair.hpp"
#include "experiments/inputs/outline_file.hpp"
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"

namespace affinterp::python {

namespace {

/// An outline given as an (n, 2) array or as the path of an outline file.
Eigen::Matrix2Xd outline(const py::object& given, const std::string& name) {
  if (py::isinstance<py::str>(given) || py::hasattr(given, "__fspath__"))
    return io::read_outline(py::str(given).cast<std::string>());
  return points(given, name);
}

py::dict pair(const py::object& source_in, const py::object& target_in, int resample, int quality_passes) {
  io::CompatiblePair pair;
  try {
    Eigen::Matrix2Xd source = outline(source_in, "source"), target = outline(target_in, "target");
    if (resample > 0) source = io::resample_outline(source, resample), target = io::resample_outline(target, resample);
    if (quality_passes < 0) value_error("quality_passes: expected a count >= 0");
    py::gil_scoped_release unlocked;
    pair = io::compatible_pair(source, target, "source", "target", quality_passes);
  } catch (const io::MeshFileError& e) {
    value_error(e.what());
  }
  py::array_t<int> F({pair.source.triangle_count(), Eigen::Index{3}});
  std::copy(pair.source.triangles.data(), pair.source.triangles.data() + pair.source.triangles.size(),
            F.mutable_data());
  py::dict out;
  out["V0"] = to_points(std::move(pair.source.vertices));
  out["V1"] = to_points(std::move(pair.target.vertices));
  out["F"] = F;
  out["steiner_vertices"] = pair.steiner_vertices;
  out["source_min_angle"] = pair.source_min_angle;
  out["target_min_angle"] = pair.target_min_angle;
  return out;
}

}  // namespace

void bind_pair(py::module_& m) {
  m.def("pair", &pair, py::arg("source"), py::arg("target"), py::kw_only(), py::arg("resample") = 0,
        py::arg("quality_passes") = 8,
        R"(Compatible triangulations of two simple polygons whose i-th vertices correspond (Aronov, Seidel and
Souvaine 1993), as `affinterp pair`: no flipped or degenerate triangle in either, by construction.
source, target: (n, 2) arrays or outline files (text 'x y' lines, or SVG); resample=N first resamples both
to N vertices at equal arc length. Returns {'V0': (N, 2), 'V1': (N, 2), 'F': (m, 3), 'steiner_vertices',
'source_min_angle', 'target_min_angle' (degrees)}; V0[:n] and V1[:n] are the outlines' vertices, ready for
Interpolation(V0, V1, F). ValueError when an outline is not a simple polygon or the counts differ.)");
}

}  // namespace affinterp::python
