#include "experiments/python/arrays.hpp"

#include <cmath>
#include <sstream>

namespace affinterp::python {

void value_error(const std::string& message) { throw py::value_error(message); }

namespace {

std::string shape_text(const py::array& a) {
  std::ostringstream text;
  text << "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text << (d ? ", " : "") << a.shape(d);
  text << (a.ndim() == 1 ? ",)" : ")");
  return text.str();
}

DoubleArray as_doubles(const py::object& a, const std::string& name) {
  const py::array raw = py::array::ensure(a);
  if (!raw) value_error(name + ": expected an array of reals");
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    value_error(name + ": expected real numbers, got dtype " + std::string(py::str(raw.dtype())));
  return DoubleArray::ensure(raw);
}

}  // namespace

void check_shape(const DoubleArray& a, const std::string& name, const std::vector<py::ssize_t>& shape,
                 const std::string& shape_words) {
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t d = 0; ok && d < shape.size(); ++d) ok = shape[d] < 0 || a.shape(d) == shape[d];
  if (!ok) value_error(name + ": expected shape " + shape_words + ", got " + shape_text(a));
}

void check_finite(const DoubleArray& a, const std::string& name) {
  const double* data = a.data();
  for (py::ssize_t k = 0; k < a.size(); ++k) {
    if (std::isfinite(data[k])) continue;
    std::ostringstream where;
    py::ssize_t rest = k;
    std::vector<py::ssize_t> index(static_cast<std::size_t>(a.ndim()));
    for (py::ssize_t d = a.ndim() - 1; d >= 0; --d) index[d] = rest % a.shape(d), rest /= a.shape(d);
    where << name << ": entry (";
    for (std::size_t d = 0; d < index.size(); ++d) where << (d ? ", " : "") << index[d];
    where << ") is " << data[k] << " (entries must be finite)";
    value_error(where.str());
  }
}

Eigen::Matrix2Xd points(const py::object& a, const std::string& name) {
  const DoubleArray v = as_doubles(a, name);
  check_shape(v, name, {-1, 2}, "(n, 2)");
  check_finite(v, name);
  return Eigen::Map<const Eigen::Matrix2Xd>(v.data(), 2, v.shape(0));
}

Eigen::Matrix3Xd points3(const py::object& a, const std::string& name) {
  const DoubleArray v = as_doubles(a, name);
  check_shape(v, name, {-1, 3}, "(n, 3)");
  check_finite(v, name);
  return Eigen::Map<const Eigen::Matrix3Xd>(v.data(), 3, v.shape(0));
}

Eigen::MatrixXi elements(const py::object& a, const std::string& name, bool tetrahedra) {
  const std::string shapes = tetrahedra ? "(m, 3) or (m, 4)" : "(m, 3)";
  const py::array raw = py::array::ensure(a);
  if (!raw) value_error(name + ": expected an " + shapes + " array of vertex indices");
  const char kind = raw.dtype().kind();
  if (kind != 'i' && kind != 'u')
    value_error(name + ": expected integer vertex indices, got dtype " + std::string(py::str(raw.dtype())));
  if (raw.ndim() != 2 || !(raw.shape(1) == 3 || (tetrahedra && raw.shape(1) == 4)))
    value_error(name + ": expected shape " + shapes + ", got " + shape_text(raw));
  const auto f = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(raw);
  const auto corners = static_cast<Eigen::Index>(raw.shape(1));
  Eigen::MatrixXi out(corners, f.shape(0));
  for (py::ssize_t k = 0; k < f.size(); ++k) {
    const long long index = f.data()[k];
    if (index < 0 || index > 0x7fffffff)
      value_error(name + ": " + (corners == 3 ? "triangle " : "tetrahedron ") + std::to_string(k / corners) +
                  " has vertex index " + std::to_string(index) + " out of range");
    out.data()[k] = static_cast<int>(index);
  }
  return out;
}

Eigen::Matrix3Xi triangles(const py::object& a, const std::string& name) { return elements(a, name, false); }

DoubleArray matrices(const py::object& a, const std::string& name, int size, bool& single) {
  DoubleArray m = as_doubles(a, name);
  const std::string words = "(" + std::to_string(size) + ", " + std::to_string(size) + ") or (k, " +
                            std::to_string(size) + ", " + std::to_string(size) + ")";
  single = m.ndim() == 2;
  if (single) {
    check_shape(m, name, {size, size}, words);
    m = DoubleArray::ensure(m.reshape({py::ssize_t{1}, py::ssize_t{size}, py::ssize_t{size}}));
  }
  check_shape(m, name, {-1, size, size}, words);
  check_finite(m, name);
  return m;
}

std::vector<double> reals(const py::object& a, const std::string& name) {
  DoubleArray t = as_doubles(a, name);
  if (t.ndim() > 1) value_error(name + ": expected a real or a 1-D sequence of reals, got shape " + shape_text(t));
  check_finite(t, name);
  return {t.data(), t.data() + t.size()};
}

py::array_t<double> to_points(Eigen::Matrix3Xd&& v) {
  auto* owned = new Eigen::Matrix3Xd(std::move(v));
  py::capsule free(owned, [](void* p) { delete static_cast<Eigen::Matrix3Xd*>(p); });
  return py::array_t<double>({owned->cols(), Eigen::Index{3}}, owned->data(), free);
}

py::array_t<double> to_points(Eigen::Matrix2Xd&& v) {
  auto* owned = new Eigen::Matrix2Xd(std::move(v));
  py::capsule free(owned, [](void* p) { delete static_cast<Eigen::Matrix2Xd*>(p); });
  return py::array_t<double>({owned->cols(), Eigen::Index{2}}, owned->data(), free);
}

}  // namespace affinterp::python
