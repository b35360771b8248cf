#include "theory/global/preconditioned_cg.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace affinterp::global {
namespace {

/// max(max Re x − min Re x, max Im x − min Im x): the extent of a frame's vertices z_k = x_k + i y_k.
template <class Scalar>
double spread(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x) {
  if (x.size() == 0) return 0;
  const double re = x.real().maxCoeff() - x.real().minCoeff();
  if constexpr (std::is_same_v<Scalar, double>)
    return re;
  else
    return std::max(re, x.imag().maxCoeff() - x.imag().minCoeff());
}

double largest_magnitude(const Eigen::VectorXd& z) { return z.cwiseAbs().maxCoeff(); }
double largest_magnitude(const Eigen::VectorXcd& z) {  // the larger of |Re| and |Im|, as spread() measures
  return std::max(z.real().cwiseAbs().maxCoeff(), z.imag().cwiseAbs().maxCoeff());
}

}  // namespace

template <class Scalar>
CgOutcome preconditioned_cg(const std::function<void(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&,
                                                     Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&)>& apply,
                            const std::function<void(Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&)>& precondition,
                            const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b,
                            Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x, const CgLimits& limits) {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  CgOutcome outcome;
  if (b.size() == 0) return outcome.converged = true, outcome;
  Vector q(b.size());
  apply(x, q);
  Vector r = b - q;  // r_0 = b − A x_0
  Vector z = r;
  precondition(z);  // z_0 = M⁻¹ r_0
  Vector p = z;
  double rho = std::real(r.dot(z));  // ⟨r, z⟩ = r* M⁻¹ r > 0 (dot conjugates its left side)
  for (;;) {
    if (!std::isfinite(rho)) return outcome;
    if (largest_magnitude(z) <= limits.tolerance * spread<Scalar>(x)) {
      x += z;  // one step of refinement: x − x_k ≈ z_k
      outcome.converged = true;
      return outcome;
    }
    if (outcome.iterations == limits.max_iterations) return outcome;
    ++outcome.iterations;
    apply(p, q);
    const double alpha = rho / std::real(p.dot(q));
    x += alpha * p;
    r -= alpha * q;
    z = r;
    precondition(z);
    const double rho_next = std::real(r.dot(z));
    p = z + (rho_next / rho) * p;
    rho = rho_next;
  }
}

template CgOutcome preconditioned_cg<double>(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>&,
                                             const std::function<void(Eigen::VectorXd&)>&, const Eigen::VectorXd&,
                                             Eigen::VectorXd&, const CgLimits&);
template CgOutcome preconditioned_cg<std::complex<double>>(
    const std::function<void(const Eigen::VectorXcd&, Eigen::VectorXcd&)>&,
    const std::function<void(Eigen::VectorXcd&)>&, const Eigen::VectorXcd&, Eigen::VectorXcd&, const CgLimits&);

}  // namespace affinterp::global
