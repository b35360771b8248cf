#include "theory/global/locus.hpp"

#include <algorithm>
#include <stdexcept>

namespace affinterp::global {
namespace {

template <int Dim>
Eigen::Spline<double, Dim> interpolating_spline(const typename BasicLocus<Dim>::Points& points) {
  if (points.cols() < 2) throw std::invalid_argument("a locus needs at least two points");
  if (!points.allFinite()) throw std::invalid_argument("a locus point is not finite");
  const Eigen::Index degree = std::min<Eigen::Index>(3, points.cols() - 1);
  const Eigen::RowVectorXd times = Eigen::RowVectorXd::LinSpaced(points.cols(), 0.0, 1.0);
  return Eigen::SplineFitting<Eigen::Spline<double, Dim>>::Interpolate(points, degree, times);
}

}  // namespace

template <int Dim>
BasicLocus<Dim>::BasicLocus(Points points) : points_(std::move(points)), spline_(interpolating_spline<Dim>(points_)) {}

template <int Dim>
typename BasicLocus<Dim>::Point BasicLocus<Dim>::at(double t) const {
  return spline_(t).matrix();
}

template class BasicLocus<2>;
template class BasicLocus<3>;

}  // namespace affinterp::global
