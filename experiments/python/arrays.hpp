#pragma once
// NumPy arrays in and out of the affinterp module: shapes checked with one-line ValueErrors, C-contiguous
// float64 (n, 2) or (n, 3) and int (m, 3) or (m, 4) arrays read in place as Eigen's column-major 2 × n and 3 × m
// matrices (the same memory), results handed to NumPy without a copy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace affinterp::python {

namespace py = pybind11;

/// float64 arrays, C order: a copy only when the caller's array has another dtype or layout.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A ValueError with `message` (one line).
[[noreturn]] void value_error(const std::string& message);

/// Checks that `a` has `shape` (-1: any length) and only finite entries; `name` starts the message, e.g.
/// "V0: expected shape (n, 2), got (3, 4)" or "V0: entry (2, 1) is nan".
void check_shape(const DoubleArray& a, const std::string& name, const std::vector<py::ssize_t>& shape,
                 const std::string& shape_words);
void check_finite(const DoubleArray& a, const std::string& name);

/// An (n, 2) array of points as the 2 × n matrix whose column k is point k (copied once).
Eigen::Matrix2Xd points(const py::object& a, const std::string& name);
/// An (m, 3) integer array of triangles as the 3 × m matrix whose column i is triangle i.
Eigen::Matrix3Xi triangles(const py::object& a, const std::string& name);
/// An (n, 3) array of points in space as the 3 × n matrix whose column k is point k (copied once).
Eigen::Matrix3Xd points3(const py::object& a, const std::string& name);
/// An (m, 3) array of triangles or, with `tetrahedra`, an (m, 4) one of tetrahedra, as the matrix whose column i
/// is element i.
Eigen::MatrixXi elements(const py::object& a, const std::string& name, bool tetrahedra = true);
/// A 2 × 2 matrix, or (k, 2, 2) matrices: the (k, 2, 2) view, and whether a single matrix was given.
DoubleArray matrices(const py::object& a, const std::string& name, int size, bool& single);
/// A real, or a 1-D sequence of reals, as a vector (finite).
std::vector<double> reals(const py::object& a, const std::string& name);

/// The 2 × n matrix as an (n, 2) array owning it, without a copy.
py::array_t<double> to_points(Eigen::Matrix2Xd&& v);
/// The 3 × n matrix as an (n, 3) array owning it, without a copy.
py::array_t<double> to_points(Eigen::Matrix3Xd&& v);

}  // namespace affinterp::python
