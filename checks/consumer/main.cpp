// A user's program against the affinterp package (installed, or its build tree): one call into each
// compiled part of affinterp::theory (and of affinterp::origin when the package has it), checked against
// known answers.
#include "theory/global/interpolation.hpp"
#include "theory/local/local.hpp"
#include "theory/sym3/affinterp.hpp"
#ifdef CONSUMER_HAS_ORIGIN
#include "theory/origin/two_triangles.hpp"
#endif
#ifdef CONSUMER_HAS_CERTIFIED
#include "theory/certified/sym3.hpp"
#endif

#include <cmath>
#include <cstdio>

int main() {
  int failures = 0;
  const auto expect = [&](bool ok, const char* what) {
    if (!ok) std::fprintf(stderr, "consumer: %s\n", what), ++failures;
  };

  // exp of diag(1, 2, 3) is diag(e, e², e³).
  const Eigen::Matrix3d E = affinterp::sym3::exp_affinterp(Eigen::Vector3d(1, 2, 3).asDiagonal());
  expect(std::abs(E(2, 2) - std::exp(3.0)) < 1e-12 * std::exp(3.0) && E(0, 1) == 0, "sym3 exponential");

  // The exp-log homotopy (Kaji eq. 3) of a quarter turn is half a quarter turn at t = 1/2.
  Eigen::Matrix2d quarter;
  quarter << 0, -1, 1, 0;
  const Eigen::Matrix2d half = affinterp::local::ExpLogHomotopy<double>::of(quarter)(0.5);
  expect(std::abs(half(1, 0) - std::sqrt(0.5)) < 1e-15, "exp-log homotopy");

  // A triangle and its translate: the global interpolation (Kaji §4, E^F with one vertex pinned) ends at
  // the target.
  affinterp::global::Mesh source, target;
  source.vertices.resize(2, 3);
  source.vertices << 0, 1, 0, 0, 0, 1;
  source.triangles.resize(3, 1);
  source.triangles << 0, 1, 2;
  target = source;
  target.vertices.row(0).array() += 2;
  affinterp::global::InterpolationOptions options;
  options.energy = affinterp::global::Energy::F;
  options.constraints.pinned = {{0, 1.0}};
  const affinterp::global::Interpolation interpolation(source, target, options);
  expect((interpolation.vertices_at(1.0) - target.vertices).norm() < 1e-12, "global interpolation");

#ifdef CONSUMER_HAS_ORIGIN
  expect(affinterp::origin::thesis_two_triangles().A.size() == 2, "origin study");
#endif
#ifdef CONSUMER_HAS_CERTIFIED
  // The certified exp of diag(1, 2, 3) certifies ours to within 10⁻¹⁵.
  const auto certified = affinterp::certified::exp(Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
  expect(certified.status == affinterp::certified::Status::certified &&
             affinterp::certified::relative_error(E, certified.value).upper() < 1e-15,
         "certified exponential");
#endif
  std::puts(failures == 0 ? "consumer: affinterp::theory works as a package" : "consumer: FAILED");
  return failures == 0 ? 0 : 1;
}
