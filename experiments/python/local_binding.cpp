// The local theory in Python: the four homotopies A(t) of one A ∈ GL⁺(2) (Kaji §3; thesis §2.2) and the
// goodness predicates of thesis Defs 2.2.1 (area) and 2.2.2 (norm), decided exactly (theory/local/goodness.hpp).
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"
#include "theory/exact/rational.hpp"
#include "theory/global/local_paths.hpp"
#include "theory/local/goodness.hpp"

#include <Eigen/LU>  // MatrixBase::determinant

#include <sstream>

namespace affinterp::python {

namespace {

py::array_t<double> homotopy_at(const py::object& A_in, const py::object& times, const std::string& name) {
  bool single = false;
  const DoubleArray a = matrices(A_in, "A", 2, single);
  if (!single) value_error("A: expected one 2x2 matrix, got shape (k, 2, 2)");
  global::LocalHomotopy homotopy{};
  try {
    homotopy = global::parse_option<global::LocalHomotopy>(name);
  } catch (const std::invalid_argument& e) {
    value_error(e.what());
  }
  const Eigen::Matrix2d A = Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(a.data());
  if (!(A.determinant() > 0)) {
    std::ostringstream message;
    message << "A: det A = " << A.determinant() << " is not positive (the homotopies join I to A in GL+(2))";
    value_error(message.str());
  }
  const std::vector<double> ts = reals(times, "t");
  const global::LocalPaths path({A}, homotopy, Eigen::VectorXd::Constant(1, global::principal_polar_angle(A)));
  py::array_t<double> out({static_cast<py::ssize_t>(ts.size()), py::ssize_t{2}, py::ssize_t{2}});
  for (std::size_t k = 0; k < ts.size(); ++k)
    Eigen::Map<Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(out.mutable_data() + 4 * k) = path.at(0, ts[k]);
  return out;
}

/// `good` of each 2×2 matrix B, at the exact rational value of its doubles.
template <bool (*good)(const local::Mat2<exact::Rational>&)>
py::object decide_each(const py::object& B_in) {
  bool single = false;
  const DoubleArray b = matrices(B_in, "B", 2, single);
  py::array_t<bool> out(b.shape(0));
  for (py::ssize_t k = 0; k < b.shape(0); ++k) {
    local::Mat2<exact::Rational> B;
    for (int e = 0; e < 4; ++e) B(e / 2, e % 2) = exact::from_double(b.data()[4 * k + e]);
    out.mutable_data()[k] = good(B);
  }
  if (single) return py::bool_(out.data()[0]);
  return out;
}

}  // namespace

void bind_local(py::module_& m) {
  m.def("homotopy_at", &homotopy_at, py::arg("A"), py::arg("t"), py::arg("homotopy") = "exp",
        R"(The local homotopy A(t) from I to A in GL+(2) (Kaji et al. §3), at each time of t: a (k, 2, 2) array.

  'exp'     A^E(t) = R_{t theta} S^t for A = R_theta S (Kaji eq. 3)
  'polar'   A^P(t) = R_{t theta}((1 - t) I + t S) (Kaji eq. 2, [ACOL00])
  'linear'  A^L(t) = (1 - t) I + t A
  'svd'     R_{t alpha}((1 - t) I + t D) R_{t beta} for A = R_alpha D R_beta
theta, alpha, beta are the principal angles in (-pi, pi]. ValueError unless det A > 0.)");
  m.def("good_for_area", &decide_each<local::good_for_area<exact::Rational>>, py::arg("B"),
        R"(Thesis Def 2.2.1 for A(t) = U(t)((1 - t) I + t B)V(t), U, V rotations: det A(t) positive and monotone on
[0, 1]. B is one 2x2 matrix (returns a bool) or a (k, 2, 2) array (returns k bools): B = A for the linear
homotopy, S (A = R S) for the polar one, D (A = R D R') for the SVD one. Decided exactly at the rational
values of the doubles.)");
  m.def("good_for_norm", &decide_each<local::good_for_norm<exact::Rational>>, py::arg("B"),
        R"(Thesis Def 2.2.2 for A(t) = U(t)((1 - t) I + t B) with a rotation U(t): |A(t) v| monotone on [0, 1] for
every unit v. B = A for the linear homotopy, S for the polar one. One 2x2 matrix (bool) or (k, 2, 2) (k bools),
decided exactly at the rational values of the doubles (Dines' theorem; theory/local/goodness.hpp).)");
}

}  // namespace affinterp::python
