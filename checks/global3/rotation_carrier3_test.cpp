// The rotation paths' carrier and remainder (theory/global3/rotation_carrier3.hpp): they compose to each element's
// rotation, reduce to the plane's consistent branch when the rotations share an axis, hold the seeds up to a half
// turn and fill in those near a full turn from their neighbours' relative turns, and are smooth across a twisted
// bar's full turns, where the consistent logarithms themselves jump.
#include "theory/global3/rotation_carrier3.hpp"
#include "checks/global3/meshes3.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/local3/local3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <numbers>

namespace {

using namespace affinterp::global3;
using affinterp::local3::rotation_exp;
using Eigen::Vector3d;
constexpr double pi = std::numbers::pi;

/// max over the dual graph's edges of |x_i − x_j|.
double largest_step(const DualGraph3& graph, const Eigen::Matrix3Xd& x) {
  double step = 0;
  for (std::size_t i = 0; i + 1 < graph.start.size(); ++i)
    for (int s = graph.start[i]; s < graph.start[i + 1]; ++s)
      step = std::max(
          step, (x.col(static_cast<Eigen::Index>(i)) - x.col(graph.neighbour[static_cast<std::size_t>(s)])).norm());
  return step;
}

/// `count` elements in a row, each sharing a facet with the next.
DualGraph3 row_graph(int count) {
  DualGraph3 row;
  row.start.push_back(0);
  for (int i = 0; i < count; ++i) {
    if (i > 0) row.neighbour.push_back(i - 1);
    if (i + 1 < count) row.neighbour.push_back(i + 1);
    row.start.push_back(static_cast<int>(row.neighbour.size()));
  }
  return row;
}

// exp [ω̄_i]× exp [η_i]× = exp [ω_i]× for every element of a twisted and bent tube, the remainder a principal
// logarithm.
TEST(RotationCarrier3, CarrierThenRemainderIsTheRotation) {
  const Mesh3 tube = meshes3::triangle_tube(24, 16, 4);
  const Interpolation3 engine(tube, meshes3::bent(meshes3::twisted(tube, 2.5 * pi, 4), 4));
  const Eigen::Matrix3Xd& omega = engine.rotation_logs();
  const RotationSplit3& split = engine.rotation_split();
  ASSERT_EQ(split.carrier.cols(), omega.cols());
  for (Eigen::Index i = 0; i < omega.cols(); ++i) {
    const Eigen::Matrix3d R = rotation_exp<double>(Vector3d(omega.col(i)));
    const Eigen::Matrix3d carried =
        rotation_exp<double>(Vector3d(split.carrier.col(i))) * rotation_exp<double>(Vector3d(split.remainder.col(i)));
    EXPECT_LT((carried - R).norm(), 1e-13) << "element " << i;
    EXPECT_LE(split.remainder.col(i).norm(), pi + 1e-12) << "element " << i;
  }
}

// Rotations about one axis (a strip in the plane z = 0 turned in it by up to 3π) commute: the remainder is
// ω_i − ω̄_i and the path exp(t ω̄_i) exp(t η_i) is exp(t ω_i), the plane's consistent branch.
TEST(RotationCarrier3, SharedAxisGivesThePlanesConsistentBranch) {
  Eigen::Matrix3Xd omega(3, 40);
  for (Eigen::Index i = 0; i < omega.cols(); ++i) omega.col(i) = Vector3d(0, 0, 3 * pi * static_cast<double>(i) / 39);
  const RotationSplit3 split = split_rotations(row_graph(40), {omega, omega});  // each seed its own logarithm
  for (Eigen::Index i = 0; i < omega.cols(); ++i) {
    EXPECT_LT((split.carrier.col(i) + split.remainder.col(i) - omega.col(i)).norm(), 1e-12) << "element " << i;
    for (double t : {0.25, 0.5, 0.9})
      EXPECT_LT((rotation_exp<double>(Vector3d(t * split.carrier.col(i))) *
                     rotation_exp<double>(Vector3d(t * split.remainder.col(i))) -
                 rotation_exp<double>(Vector3d(t * omega.col(i))))
                    .norm(),
                1e-12)
          << "element " << i << ", t = " << t;
  }
}

// A seed is held fully up to a half turn, then less as the exponential's gain across its axis falls, least on the
// singular sphere: continuous at π, decreasing to 2π, rising again to 3π.
TEST(RotationCarrier3, SeedFidelityFollowsTheExponentialsGain) {
  EXPECT_EQ(seed_fidelity(0.0), max_seed_fidelity);
  EXPECT_EQ(seed_fidelity(pi), max_seed_fidelity);
  EXPECT_GT(seed_fidelity(pi + 1e-4), 100.0);
  double previous = max_seed_fidelity;
  for (double angle = pi + 0.1; angle < 2 * pi; angle += 0.1) {
    EXPECT_LT(seed_fidelity(angle), previous) << "angle " << angle;
    previous = seed_fidelity(angle);
  }
  EXPECT_EQ(seed_fidelity(2 * pi), min_seed_fidelity);
  EXPECT_NEAR(seed_fidelity(3 * pi), 1.0 / 80, 1e-12);  // w = (σ(3π)/σ(π))⁴ = 1/81
}

// A row of elements turning about z by 0.8 rad more each, the seed of the one nearest the full turn (6.4 rad) given
// the same length across the row (x): the fill puts it back along z, between its neighbours, through the free end's
// relative turns too, and holds the seeds up to a half turn as they are.
TEST(RotationCarrier3, FillReplacesASeedOnTheSingularSphereByItsNeighbours) {
  constexpr int count = 11;
  Eigen::Matrix3Xd omega(3, count);
  for (int i = 0; i < count; ++i) omega.col(i) = Vector3d(0, 0, 0.8 * i);
  Eigen::Matrix3Xd seed = omega;
  seed.col(8) = Vector3d(6.4, 0, 0);
  const Eigen::Matrix3Xd filled = filled_seeds(row_graph(count), {omega, seed});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(filled.col(i), seed.col(i)) << "element " << i;
  for (int i = 4; i < count; ++i) EXPECT_LT((filled.col(i) - omega.col(i)).norm(), 0.05) << "element " << i;
}

// The walk carries the turn count through each full turn of a bar twisted by 5π, where elements near 2π and 4π
// have no logarithm within 1 rad of their neighbours' (those exactly at a full turn, none along the bar at all): the
// carrier follows the twist along the whole bar (without the walk's prediction from the relative turns, the walk lost
// two turns a little past 2π and the frames were 1.7 widths off).
TEST(RotationCarrier3, CarrierFollowsTheTwistThroughTwoFullTurns) {
  const Mesh3 bar = meshes3::tetrahedral_bar(30, 10, 0.1);
  const Interpolation3 engine(bar, meshes3::twisted(bar, 5 * pi, 10));
  const Eigen::Matrix3Xd& carrier = engine.rotation_split().carrier;
  for (Eigen::Index i = 0; i < carrier.cols(); ++i) {
    const double twist = 5 * pi * (static_cast<double>(i / 6) + 0.5) / 30;  // six tetrahedra a box
    EXPECT_NEAR(carrier(0, i), twist, 0.5) << "element " << i;
    EXPECT_LT(carrier.col(i).tail<2>().norm(), 0.1) << "element " << i;
  }
}

// On the 3π bar the consistent logarithms jump by about 2π at the full turn (elements whose every logarithm lies
// across the bar); the carrier steps by less than a radian between neighbours and the remainders stay small.
TEST(RotationCarrier3, CarrierIsSmoothAcrossTheBarsFullTurn) {
  const Mesh3 bar = meshes3::tetrahedral_bar(30, 10, 0.1);
  const Interpolation3 engine(bar, meshes3::twisted(bar, 3 * pi, 10));
  const DualGraph3 graph = dual_graph3(bar.elements);
  const double omega_step = largest_step(graph, engine.rotation_logs());
  const double carrier_step = largest_step(graph, engine.rotation_split().carrier);
  const double remainder = engine.rotation_split().remainder.colwise().norm().maxCoeff();
  std::cout << "3pi bar, largest step between neighbours: logarithms " << omega_step << ", carrier " << carrier_step
            << "; largest remainder " << remainder << "\n";
  EXPECT_GT(omega_step, 5.0);
  EXPECT_LT(carrier_step, 1.0);
  EXPECT_LT(remainder, 1.0);
}

}  // namespace
