// The as-rigid-as-possible refinement of 3D frames (theory/global3/arap_refinement3.hpp): its energy never rises,
// it keeps the ends and the blend's poses, it gives back volume where pins pull a bending bar along a chord, its
// frames do not depend on the number of threads, and bad iteration counts are refused.
#include "theory/global3/arap_refinement3.hpp"
#include "checks/global3/meshes3.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/global3/blend3.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/interpolation3.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace arap_refinement3_test {

using namespace affinterp::global3;
using meshes3::box_diagonal;

/// The bar of length 10 (tetrahedra) or the tube of length 4 (triangles), and the same bent into a quarter
/// circle about z (the bar's axis onto the arc of radius 20/π through the origin).
struct Bend {
  Mesh3 source, target;
  double length;
};

Bend quarter_bend(bool tetrahedra) {
  const double length = tetrahedra ? 10 : 4;
  Bend bend{tetrahedra ? meshes3::tetrahedral_bar(20, length) : meshes3::triangle_tube(8, 8, length), {}, length};
  bend.target = bend.source;
  const double radius = length / (std::numbers::pi / 2);
  for (Eigen::Index k = 0; k < bend.source.vertex_count(); ++k) {
    const Eigen::Vector3d p = bend.source.vertices.col(k);
    const double phi = p.x() / radius;
    bend.target.vertices.col(k) << (radius - p.y()) * std::sin(phi), radius - (radius - p.y()) * std::cos(phi), p.z();
  }
  return bend;
}

/// Both ends' vertices pinned (weight 100): the free end then moves along the chord, not the arc its maps follow.
Interpolation3Options pinned_ends(const Bend& bend, int arap_iterations) {
  Interpolation3Options options;
  options.constraints.barycentre.reset();
  for (Eigen::Index k = 0; k < bend.source.vertex_count(); ++k) {
    const double x = bend.source.vertices(0, k);
    if (x == 0 || x == bend.length) options.constraints.pinned.push_back({k, 100});
  }
  options.arap_iterations = arap_iterations;
  return options;
}

// Each local step minimises over the rotations and each global step over the vertices, so E^ARAP of the
// iterates never rises; here it also falls, the pins being at odds with the maps.
TEST(ArapRefinement3, EnergyNeverRises) {
  for (const bool tetrahedra : {true, false}) {
    const Bend bend = quarter_bend(tetrahedra);
    const Interpolation3 plain(bend.source, bend.target, pinned_ends(bend, 0));
    const double t = 0.5;
    const std::vector<Eigen::Matrix3d> A = plain.local_maps_at(t);
    const ConstraintTargets3 targets = plain.targets_at(t);
    Eigen::Matrix3Xd v = plain.vertices_at(t);
    const double first = arap_energy(plain.system(), A, v, targets);
    double previous = first;
    for (int k = 1; k <= 8; ++k) {
      v = arap_refined(plain.system(), A, targets, std::move(v), 1, 1);
      const double energy = arap_energy(plain.system(), A, v, targets);
      EXPECT_LE(energy, previous * (1 + 1e-12)) << (tetrahedra ? "bar" : "tube") << ", iteration " << k;
      previous = energy;
    }
    EXPECT_LT(previous, 0.9 * first) << (tetrahedra ? "bar" : "tube");
  }
}

// At t = 0 and 1 (and at a blend's unit weights) the E^F frame fits its maps exactly: B_i = A_i on the element's
// span, whose nearest rotation to B_i A_iᵀ is I, so the refinement leaves the frame where it is.
TEST(ArapRefinement3, KeepsTheEndsAndThePoses) {
  for (const bool tetrahedra : {true, false}) {
    const Bend bend = quarter_bend(tetrahedra);
    Interpolation3Options options;
    options.arap_iterations = 4;
    const Interpolation3 refined(bend.source, bend.target, options);
    const double box = box_diagonal(bend.target.vertices);
    EXPECT_LT((refined.vertices_at(0.0) - bend.source.vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    EXPECT_LT((refined.vertices_at(1.0) - bend.target.vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
    Blend3Options blend_options;
    blend_options.arap_iterations = 4;
    const Blend3 blend({bend.source, bend.target, meshes3::twisted(bend.source, 1.5 * std::numbers::pi, bend.length)},
                       blend_options);
    EXPECT_LT((blend.vertices_at(Eigen::Vector3d(0, 1, 0)) - bend.target.vertices).cwiseAbs().maxCoeff(), 1e-9 * box);
  }
}

// Pinned to the chord, E^F's bar shortens (its maps turn each element along the arc); letting the elements turn
// gives back much of the lost volume: 0.891 of the source's with E^F, 0.925 after 20 steps.
TEST(ArapRefinement3, GivesBackVolumeWherePinsPullAlongTheChord) {
  const Bend bend = quarter_bend(true);
  const double lost_plain =
      1 - frame_metrics3(bend.source, Interpolation3(bend.source, bend.target, pinned_ends(bend, 0)).vertices_at(0.5))
              .measure_ratio;
  const double lost_refined =
      1 - frame_metrics3(bend.source, Interpolation3(bend.source, bend.target, pinned_ends(bend, 20)).vertices_at(0.5))
              .measure_ratio;
  EXPECT_GT(lost_plain, 0.1);
  EXPECT_LT(lost_refined, 0.8 * lost_plain);
}

TEST(ArapRefinement3, FramesAreTheSameOnAnyNumberOfThreads) {
  const Bend bend = quarter_bend(false);
  Interpolation3Options one = pinned_ends(bend, 3), two = one;
  one.frame_threads = 1, two.frame_threads = 2;
  EXPECT_EQ(Interpolation3(bend.source, bend.target, one).vertices_at(0.3),
            Interpolation3(bend.source, bend.target, two).vertices_at(0.3));
}

TEST(ArapRefinement3, RefusesACountOutOfRange) {
  const Bend bend = quarter_bend(false);
  for (const int count : {-1, max_arap_iterations + 1}) {
    EXPECT_THROW(Interpolation3(bend.source, bend.target, pinned_ends(bend, count)), affinterp::global::RefusedProblem);
    Blend3Options options;
    options.arap_iterations = count;
    EXPECT_THROW(Blend3({bend.source, bend.target}, options), affinterp::global::RefusedProblem);
  }
}

}  // namespace arap_refinement3_test
