#include "theory/origin/frame_interpolation.hpp"

#include "theory/exact/rational.hpp"
#include "theory/local/exp_log_homotopy.hpp"
#include "theory/origin/affine_frames.hpp"
#include "theory/origin/energy.hpp"
#include "theory/origin/symbols.hpp"

#include <Eigen/LU>

#include <stdexcept>

namespace affinterp::origin {
namespace {

/// The exact rational values of the doubles in M (GiNaC's floating-point solve pivots without regard to
/// size, so the minimisation is done exactly and rounded once at the end).
GiNaC::matrix to_ginac(const Eigen::MatrixXd& M) {
  GiNaC::matrix result(M.rows(), M.cols());
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    for (Eigen::Index c = 0; c < M.cols(); ++c)
      result(r, c) = GiNaC::numeric(exact::to_string(exact::from_double(M(r, c))).c_str());
  return result;
}

double to_double(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }

Eigen::Matrix3d to_eigen(const GiNaC::matrix& M) {
  Eigen::Matrix3d result;
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) result(r, c) = to_double(M(r, c));
  return result;
}

Eigen::Matrix3d shift(const Eigen::Vector2d& o) {
  Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
  T.topRightCorner<2, 1>() = o;
  return T;
}

/// A^E(t) = R_{tθ} S^t for L = R_θ S (Kaji eq. (3)), the local theory's exp-log homotopy.
Eigen::Matrix2d exponential_interpolation(const Eigen::Matrix2d& L, double t) {
  if (!(L.determinant() > 0)) throw std::invalid_argument("local_interpolation: det A must be positive");
  return local::ExpLogHomotopy<double>::of(L)(t);
}

}  // namespace

Eigen::Matrix3d local_interpolation(const Eigen::Matrix3d& A, const Eigen::Vector2d& o, double t) {
  const Eigen::Matrix3d in_frame = shift(-o) * A * shift(o);  // T(A, −o)
  Eigen::Matrix3d A_t = Eigen::Matrix3d::Identity();
  A_t.topLeftCorner<2, 2>() = exponential_interpolation(in_frame.topLeftCorner<2, 2>(), t);
  A_t.topRightCorner<2, 1>() = t * in_frame.topRightCorner<2, 1>();
  return shift(o) * A_t * shift(-o);  // back to world coordinates: T(A_t, o)
}

Eigen::Matrix<double, 2, 4> global_interpolation(const TwoTriangles& config,
                                                 const std::array<Eigen::Vector2d, 2>& origins, double t) {
  const Symbols& s = symbols();
  std::array<GiNaC::matrix, 2> A_t;
  for (unsigned i = 0; i < 2; ++i) A_t[i] = to_ginac(local_interpolation(to_eigen(config.A[i]), origins[i], t));
  const GiNaC::ex E = energy_E2(A_t[0], A_t[1], intermediate_map(config, 0, s.v), intermediate_map(config, 1, s.v),
                                to_ginac(origins[0]), to_ginac(origins[1]));
  const Minimum m = minimise(E, s.unknowns);
  Eigen::Matrix<double, 2, 4> v;
  for (unsigned k = 0; k < 4; ++k)
    for (unsigned r = 0; r < 2; ++r) v(r, k) = to_double(s.v(r, k).subs(m.minimiser));
  return v;
}

}  // namespace affinterp::origin
