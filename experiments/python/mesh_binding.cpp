// affinterp.read_mesh: a 2D triangle mesh file as arrays, read and checked as `affinterp interpolate` reads
// its --source and --target (experiments/inputs/mesh_file.hpp).
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"

#include <pybind11/stl.h>

namespace affinterp::python {

namespace {

py::tuple read_mesh(const py::object& path) {
  global::Mesh mesh;
  try {
    mesh = io::read_mesh(py::str(path).cast<std::string>());
  } catch (const io::MeshFileError& e) {
    value_error(e.what());
  }
  py::array_t<int> F({mesh.triangle_count(), Eigen::Index{3}});
  std::copy(mesh.triangles.data(), mesh.triangles.data() + mesh.triangles.size(), F.mutable_data());
  return py::make_tuple(to_points(std::move(mesh.vertices)), F);
}

}  // namespace

void bind_mesh(py::module_& m) {
  m.def("read_mesh", &read_mesh, py::arg("path"),
        R"((V, F) of a 2D triangle mesh file, as `affinterp interpolate` reads it: V the (n, 2) vertices p_k, F the
(m, 3) triangles (0-based). ValueError with the reader's one-line message ("FILE:LINE: problem").)");
}

}  // namespace affinterp::python
