// 3×3 symmetric matrices in Python (thesis ch. 3): exp S and the eigenvalues of S by ours, the algorithm of
// theory/sym3/affinterp.hpp, over one matrix or a (k, 3, 3) array.
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"
#include "theory/sym3/affinterp.hpp"

#include <sstream>

namespace affinterp::python {

namespace {

using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

/// f(S) for each symmetric S of `S_in`, `rows` × `cols` each, shaped as the input (one or k).
template <int rows, int cols, class Function>
py::array_t<double> each_symmetric(const py::object& S_in, Function f) {
  bool single = false;
  const DoubleArray s = matrices(S_in, "S", 3, single);
  const py::ssize_t k = s.shape(0);
  for (py::ssize_t n = 0; n < k; ++n)
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (s.data()[9 * n + 3 * i + j] != s.data()[9 * n + 3 * j + i]) {
          std::ostringstream message;
          message.precision(17);
          message << "S" << (single ? "" : "[" + std::to_string(n) + "]") << ": not symmetric: entry (" << i + 1 << ","
                  << j + 1 << ") = " << s.data()[9 * n + 3 * i + j] << " but (" << j + 1 << "," << i + 1
                  << ") = " << s.data()[9 * n + 3 * j + i];
          value_error(message.str());
        }
  std::vector<py::ssize_t> shape{k, rows};
  if (cols > 1) shape.push_back(cols);
  if (single) shape.erase(shape.begin());
  py::array_t<double> out(shape);
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t n = 0; n < k; ++n)
      Eigen::Map<Eigen::Matrix<double, rows, cols, cols == 1 ? Eigen::ColMajor : Eigen::RowMajor>>(
          out.mutable_data() + rows * cols * n) = f(sym3::Mat3(Eigen::Map<const RowMajor3>(s.data() + 9 * n)));
  }
  return out;
}

}  // namespace

void bind_sym3(py::module_& m) {
  m.def(
      "exp3", [](const py::object& S) { return each_symmetric<3, 3>(S, sym3::exp_affinterp); }, py::arg("S"),
      R"(exp S for S in Sym(3) (thesis ch. 3), by ours (`affinterp exp3`): one 3x3 matrix or a (k, 3, 3) array.
Where exp S is finite in double, |X - exp S|_F <= 2e-15 max(1, |S|_2) |exp S|_F; where it overflows
(largest eigenvalue beyond log DBL_MAX ~ 709.78) the result has infinite or NaN entries. ValueError on a
non-symmetric or non-finite S.)");
  m.def(
      "eig3", [](const py::object& S) { return each_symmetric<3, 1>(S, sym3::eigenvalues_affinterp); }, py::arg("S"),
      R"(The eigenvalues of S in Sym(3), ascending (`affinterp eig3`), each within 4e-15 max(1, |S|_2):
shape (3,) for one matrix, (k, 3) for a (k, 3, 3) array.)");
}

}  // namespace affinterp::python
