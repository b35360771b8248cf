// The 3D engine (theory/global3/interpolation3.hpp) on generated bars of tetrahedra and tubes of triangles: its
// ends, its minimiser against a dense least-squares one, its local maps against theory/local3, the 3π twisted
// bar, and batch frames against frames one at a time.
#include "theory/global3/interpolation3.hpp"
#include "checks/global3/meshes3.hpp"
#include "theory/global/locus.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/local_maps3.hpp"
#include "theory/local3/local3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <numbers>

namespace interpolation3_test {

using namespace affinterp::global3;
using affinterp::global::LocalHomotopy;
using affinterp::global::RotationBranch;
using meshes3::box_diagonal;
constexpr double pi = std::numbers::pi;

/// Default options changed by `set`.
template <class Set>
Interpolation3Options options(Set set) {
  Interpolation3Options o;
  set(o);
  return o;
}

Constraints3 pins(std::vector<affinterp::global::PinnedVertex> pinned, bool barycentre) {
  Constraints3 c;
  c.pinned = std::move(pinned);
  if (!barycentre) c.barycentre.reset();
  return c;
}

/// A locus of `vertex` through three points, and a barycentre through two (its locus, not its line).
Constraints3 with_loci(Eigen::Index vertex, double weight) {
  Constraints3 c;
  Eigen::Matrix3Xd points(3, 3), barycentre(3, 2);
  points << 0, 1, 3, 0.5, 2, 1, -1, 0, 2;
  barycentre << 0, 1, 0.5, 0.2, 0, -0.3;
  c.loci.push_back({vertex, points, weight});
  c.barycentre->points = barycentre;
  return c;
}

affinterp::global::PinnedVertex pin(Eigen::Index vertex, double weight) {
  affinterp::global::PinnedVertex p;
  p.vertex = vertex;
  p.weight = weight;
  return p;
}

struct Pair {
  const char* name;
  Mesh3 source, target;
};

std::vector<Pair> pairs() {
  const Mesh3 bar = meshes3::tetrahedral_bar(6, 4), tube = meshes3::triangle_tube(6, 8, 4);
  return {{"bar", bar, meshes3::bent(meshes3::twisted(bar, 2.5, 4), 4)},
          {"tube", tube, meshes3::bent(meshes3::twisted(tube, 2.5, 4), 4)}};
}

constexpr LocalHomotopy homotopies[] = {LocalHomotopy::exp, LocalHomotopy::polar, LocalHomotopy::linear,
                                        LocalHomotopy::svd};

// At t = 0 every A_i(0) = I and at t = 1 A_i(1) = A_i, whose in-span parts the source and the target meet exactly
// (E^F = 0 there), with the barycentre on its line: the ends are the meshes, to rounding.
TEST(Interpolation3, EndsAreTheSourceAndTheTarget) {
  for (const Pair& pair : pairs())
    for (LocalHomotopy homotopy : homotopies)
      for (RotationBranch branch : {RotationBranch::consistent, RotationBranch::principal}) {
        const Interpolation3 engine(pair.source, pair.target,
                                    options([&](auto& o) { o.homotopy = homotopy, o.rotation_branch = branch; }));
        const double box = box_diagonal(pair.target.vertices);
        EXPECT_LT((engine.vertices_at(0.0) - pair.source.vertices).cwiseAbs().maxCoeff(), 1e-9 * box) << pair.name;
        EXPECT_LT((engine.vertices_at(1.0) - pair.target.vertices).cwiseAbs().maxCoeff(), 1e-9 * box) << pair.name;
      }
}

/// The minimiser of Σ_s w_s ‖(X_s − A_s E_s) E_s⁺‖²_F + Σ c‖v_k − r_k‖² + c_o ‖mean v − u‖², written as one dense
/// least-squares problem in the 3n coordinates (row by row from the definition) and solved by QR; the terms s run
/// over the elements of each rest pose in turn (one pose, or the source and the target when symmetrised).
Eigen::Matrix3Xd dense_minimiser(const std::vector<const Mesh3*>& rests, const std::vector<Eigen::Matrix3d>& A,
                                 const Eigen::VectorXd& w, const Constraints3& constraints,
                                 const ConstraintTargets3& targets) {
  const Eigen::Index n = rests.front()->vertex_count(), d = rests.front()->corners() - 1;
  const Eigen::Index m = rests.front()->element_count();
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> rhs;
  for (Eigen::Index s = 0; s < m * static_cast<Eigen::Index>(rests.size()); ++s) {
    const Mesh3& rest = *rests[static_cast<std::size_t>(s / m)];
    const Eigen::Index i = s % m;
    Eigen::MatrixXd E(3, d);
    for (Eigen::Index c = 1; c <= d; ++c) E.col(c - 1) = rest.corner(i, static_cast<int>(c)) - rest.corner(i, 0);
    const Eigen::MatrixXd pinv = E.completeOrthogonalDecomposition().pseudoInverse();  // d × 3
    const Eigen::MatrixXd target = A[static_cast<std::size_t>(s)] * E * pinv;
    for (int r = 0; r < 3; ++r)  // residual entry (r, col) = Σ_c (x_c − x_0)_r pinv(c, col) − target(r, col)
      for (int col = 0; col < 3; ++col) {
        Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(3 * n);
        for (Eigen::Index c = 1; c <= d; ++c) {
          row[3 * rest.elements(c, i) + r] += std::sqrt(w[s]) * pinv(c - 1, col);
          row[3 * rest.elements(0, i) + r] -= std::sqrt(w[s]) * pinv(c - 1, col);
        }
        rows.push_back(row);
        rhs.push_back(std::sqrt(w[s]) * target(r, col));
      }
  }
  const std::vector<affinterp::global::PinnedVertex> terms = vertex_terms(constraints);  // pins, then loci
  for (std::size_t j = 0; j < terms.size(); ++j)
    for (int r = 0; r < 3; ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(3 * n);
      row[3 * terms[j].vertex + r] = std::sqrt(terms[j].weight);
      rows.push_back(row);
      rhs.push_back(std::sqrt(terms[j].weight) * targets.vertices(r, static_cast<Eigen::Index>(j)));
    }
  if (constraints.barycentre)
    for (int r = 0; r < 3; ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(3 * n);
      const double c = std::sqrt(constraints.barycentre->weight);
      for (Eigen::Index k = 0; k < n; ++k) row[3 * k + r] = c / static_cast<double>(n);
      rows.push_back(row);
      rhs.push_back(c * targets.barycentre[r]);
    }
  Eigen::MatrixXd J(static_cast<Eigen::Index>(rows.size()), 3 * n);
  for (std::size_t k = 0; k < rows.size(); ++k) J.row(static_cast<Eigen::Index>(k)) = rows[k];
  const Eigen::VectorXd x =
      J.colPivHouseholderQr().solve(Eigen::Map<Eigen::VectorXd>(rhs.data(), static_cast<Eigen::Index>(rhs.size())));
  return Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n);
}

TEST(Interpolation3, IsTheDenseLeastSquaresMinimiser) {
  const std::vector<Constraints3> constraint_sets{pins({}, true),  // the barycentre's line alone
                                                  pins({pin(0, 2.0), pin(5, 0.5)}, true),  // pins and the barycentre
                                                  pins({pin(3, 1.0)}, false),              // a pin alone
                                                  with_loci(4, 2.0)};  // a vertex locus, the barycentre's spline
  const Mesh3 bar = meshes3::tetrahedral_bar(2, 2), tube = meshes3::triangle_tube(2, 5, 2);
  for (const Pair& pair : {Pair{"bar", bar, meshes3::bent(meshes3::twisted(bar, 1.5, 2), 2)},
                           Pair{"tube", tube, meshes3::bent(meshes3::twisted(tube, 1.5, 2), 2)}})
    for (const Constraints3& constraints : constraint_sets)
      for (bool area_weighted : {true, false}) {
        const Interpolation3 engine(pair.source, pair.target, options([&](auto& o) {
                                      o.area_weighted = area_weighted, o.constraints = constraints;
                                    }));
        for (double t : {0.3, 0.7}) {
          const Eigen::Matrix3Xd v = engine.vertices_at(t);
          const Eigen::Matrix3Xd reference = dense_minimiser(
              {&pair.source}, engine.local_maps_at(t), engine.system().weights(), constraints, engine.targets_at(t));
          EXPECT_LT((v - reference).cwiseAbs().maxCoeff(), 1e-10 * box_diagonal(reference)) << pair.name;
          EXPECT_LE(engine.energy_at(t, v), engine.energy_at(t, reference) * (1 + 1e-12) + 1e-14) << pair.name;
        }
      }
}

// A vertex locus of large weight is followed: v_k(t) is its B-spline (global/locus.hpp) through the points at
// t = 0, 1/2, 1 to within c⁻¹ of the frame's size; a locus refused with one line: one point, a NaN, no such vertex.
TEST(Interpolation3, AVertexLocusOfLargeWeightIsFollowed) {
  const Mesh3 tube = meshes3::triangle_tube(4, 8, 4);
  const Mesh3 target = meshes3::bent(meshes3::twisted(tube, 1.5, 4), 4);
  Constraints3 c = with_loci(5, 1e8);
  c.loci[0].points.col(0) = tube.vertices.col(5);  // starting where the vertex is
  const Interpolation3 engine(tube, target, options([&](auto& o) { o.constraints = c; }));
  const affinterp::global::Locus3 u(c.loci[0].points);
  for (double t : {0.0, 0.25, 0.5, 0.8})
    EXPECT_LT((engine.vertices_at(t).col(5) - u.at(t)).norm(), 1e-6) << "t = " << t;
  for (auto [points, what] : {std::pair{Eigen::Matrix3Xd(Eigen::Matrix3Xd::Zero(3, 1)), "two points"},
                              std::pair{Eigen::Matrix3Xd(Eigen::Matrix3Xd::Constant(3, 2, NAN)), "not finite"}}) {
    Constraints3 bad = c;
    bad.loci[0].points = points;
    EXPECT_THROW(Interpolation3(tube, target, options([&](auto& o) { o.constraints = bad; })),
                 affinterp::global::RefusedProblem)
        << what;
  }
  Constraints3 out_of_range = c;
  out_of_range.loci[0].vertex = tube.vertex_count();
  EXPECT_THROW(Interpolation3(tube, target, options([&](auto& o) { o.constraints = out_of_range; })),
               affinterp::global::RefusedProblem);
}

// Symmetrised, E′(t) = E(t) + E^{−1}(1 − t) is the dense minimiser of both sums, the reverse terms fitting the
// target's elements to the homotopies of the reverse maps A_i⁻¹ at 1 − t with logarithms −ω_i (the forward engine's
// local maps of the swapped pair, whose consistent walk gives −ω_i); the ends are the meshes, and swapping source
// and target gives the same frames at 1 − t. SVD is left out of the swap: its reverse paths decompose A_i⁻¹, whose
// factors' logarithms are not A_i's negated, so only its ends are checked.
TEST(Interpolation3, SymmetrisedIsTheMinimiserOfBothSumsAndSwapsSourceAndTarget) {
  for (const Pair& pair : pairs())
    for (LocalHomotopy homotopy : homotopies) {
      const auto symmetric = options([&](auto& o) { o.homotopy = homotopy, o.symmetric = true; });
      const Interpolation3 engine(pair.source, pair.target, symmetric), swapped(pair.target, pair.source, symmetric);
      const double box = box_diagonal(pair.target.vertices);
      EXPECT_LT((engine.vertices_at(0.0) - pair.source.vertices).cwiseAbs().maxCoeff(), 1e-9 * box) << pair.name;
      EXPECT_LT((engine.vertices_at(1.0) - pair.target.vertices).cwiseAbs().maxCoeff(), 1e-9 * box) << pair.name;
      if (homotopy == LocalHomotopy::svd) continue;
      for (double t : {0.3, 0.7}) {
        std::vector<Eigen::Matrix3d> A = engine.local_maps_at(t);
        const std::vector<Eigen::Matrix3d> reverse = swapped.local_maps_at(1 - t);
        A.insert(A.end(), reverse.begin(), reverse.end());
        const Eigen::Matrix3Xd v = engine.vertices_at(t);
        const Eigen::Matrix3Xd reference = dense_minimiser({&pair.source, &pair.target}, A, engine.system().weights(),
                                                           engine.options().constraints, engine.targets_at(t));
        EXPECT_LT((v - reference).cwiseAbs().maxCoeff(), 1e-10 * box) << pair.name << " t = " << t;
        EXPECT_LT((v - swapped.vertices_at(1 - t)).cwiseAbs().maxCoeff(), 1e-10 * box) << pair.name << " t = " << t;
      }
    }
}

// The batched local maps are the local3 homotopies of each element (exp-log through sym3::exp_batched): on the
// principal branch R_i^t S_i^t itself, on the consistent branch with R_i^t's turn along the carrier and remainder,
// exp(t ω̄_i) exp(t η_i) S_i^t.
TEST(Interpolation3, LocalMapsAreTheLocal3Homotopies) {
  const Pair pair = pairs()[0];
  const std::vector<Eigen::Matrix3d> A = [&] {
    const Interpolation3 ends(pair.source, pair.target, options([](auto& o) { o.homotopy = LocalHomotopy::linear; }));
    return ends.local_maps_at(1.0);
  }();
  const Interpolation3 consistent(pair.source, pair.target);
  const Interpolation3 principal(pair.source, pair.target,
                                 options([](auto& o) { o.rotation_branch = RotationBranch::principal; }));
  const double t = 0.4;
  const std::vector<Eigen::Matrix3d> maps = consistent.local_maps_at(t), principal_maps = principal.local_maps_at(t);
  const RotationSplit3& split = consistent.rotation_split();
  for (std::size_t i = 0; i < A.size(); ++i) {
    const auto e = static_cast<Eigen::Index>(i);
    const affinterp::local3::Svd3<double> d = affinterp::local3::svd3<double>(A[i]);
    const affinterp::local3::ExpLogHomotopy3<double> path(principal.rotation_logs().col(e), d);
    EXPECT_LT((principal_maps[i] - path(t)).norm(), 1e-13 * A[i].norm());
    const Eigen::Matrix3d carried =
        affinterp::local3::rotation_exp<double>(Eigen::Vector3d(t * split.carrier.col(e))) *
        affinterp::local3::rotation_exp<double>(Eigen::Vector3d(t * split.remainder.col(e))) * path.stretch_power(t);
    EXPECT_LT((maps[i] - carried).norm(), 1e-13 * A[i].norm());
  }
}

/// Max over the vertices (those with |x − x_skip| > skip_radius) of |v − exact| over the bar's width.
double twist_error(const Eigen::Matrix3Xd& v, const Mesh3& exact, double width, double x_skip, double skip_radius) {
  double error = 0;
  for (Eigen::Index k = 0; k < v.cols(); ++k)
    if (std::abs(exact.vertices(0, k) - x_skip) > skip_radius)
      error = std::max(error, (v.col(k) - exact.vertices.col(k)).norm() / width);
  return error;
}

// A bar (length 10, width 1/10, 30 boxes) twisted by `turn` along its length: its in-between pose at t = 1/2 is
// the bar twisted by turn/2. Not exactly: the twist shears each tetrahedron (by the twist rate times its distance
// from the axis), and exp-log's R^t S^t of a sheared element is not half the twist; the bar is thin so that the
// shear is small. The consistent branch gives the elements beyond π their turns; the principal branch turns them
// the short way round, by about a width off.
TEST(Interpolation3, TwistedBarBeyondPiMatchesItsExactHalfwayPose) {
  constexpr double length = 10, width = 0.1;
  const Mesh3 bar = meshes3::tetrahedral_bar(30, length, width);
  const auto principal = options([](auto& o) { o.rotation_branch = RotationBranch::principal; });
  const Mesh3 target = meshes3::twisted(bar, 1.8 * pi, length), halfway = meshes3::twisted(bar, 0.9 * pi, length);
  const double error = twist_error(Interpolation3(bar, target).vertices_at(0.5), halfway, width, 0, -1);
  const double principal_error =
      twist_error(Interpolation3(bar, target, principal).vertices_at(0.5), halfway, width, 0, -1);
  std::cout << "1.8pi bar at t = 1/2, max vertex error / width: consistent " << error << ", principal "
            << principal_error << "\n";
  EXPECT_LT(error, 0.1);
  EXPECT_GT(principal_error, 1.0);
  EXPECT_EQ(frame_metrics3(bar, Interpolation3(bar, target).vertices_at(0.5)).inverted_elements, 0);
}

// Twisted by 3π, the elements at twist 2π lie on the exponential's singular sphere (rotation_carrier3.hpp): no
// logarithm of theirs gives their halfway turn, and their paths exp(t ω_i) would leave the frame about a width off
// at that section. Turned along the filled and smoothed carrier they follow their neighbours: the consistent branch
// matches the exact halfway pose at every vertex, on the bar in 30 to 240 boxes (the finer, the more elements near
// the full turn: 0.17, 0.10, 0.06 and 0.04 widths on an AVX-512 build and on the x86-64 baseline alike; without the
// fill and the walk's prediction 120 and 240 boxes were 0.77 and 1.47 widths off, and 0.28 and 0.91 on the
// baseline); the principal one is off by a width beyond π.
TEST(Interpolation3, TwistedBarThreePiMatchesItsExactHalfwayPose) {
  constexpr double length = 10, width = 0.1;
  for (const int boxes : {30, 60, 120, 240}) {
    const Mesh3 bar = meshes3::tetrahedral_bar(boxes, length, width);
    const Mesh3 target = meshes3::twisted(bar, 3 * pi, length), halfway = meshes3::twisted(bar, 1.5 * pi, length);
    const Interpolation3 consistent(bar, target);
    const Interpolation3 principal(bar, target,
                                   options([](auto& o) { o.rotation_branch = RotationBranch::principal; }));
    const double error = twist_error(consistent.vertices_at(0.5), halfway, width, 0, -1);
    const double principal_error = twist_error(principal.vertices_at(0.5), halfway, width, 0, -1);
    std::cout << "3pi bar in " << boxes << " boxes at t = 1/2, max vertex error / width: consistent " << error
              << ", principal " << principal_error << "\n";
    EXPECT_LT(error, 0.35) << boxes << " boxes";
    EXPECT_GT(principal_error, 1.0) << boxes << " boxes";
    EXPECT_NEAR(consistent.rotation_logs().colwise().norm().maxCoeff(), 3 * pi, 0.1) << boxes << " boxes";
  }
}

// Twisted by 5π, through two full turns: the frames at t = 1/4, 1/2 and 3/4 match the bar twisted by 5πt at every
// vertex, in 30 boxes and in 120 (0.32 and 0.09 widths). With seeds held by the square of the exponential's gain
// instead of its fourth power, the carrier tilted 0.06 rad where it neared 4π, and the sections there turned 0.1
// rad wrong at t = 1/4 and 3/4 (1.2 widths off in 120 boxes).
TEST(Interpolation3, TwistedBarFivePiMatchesItsExactPoses) {
  constexpr double length = 10, width = 0.1;
  for (const int boxes : {30, 120}) {
    const Mesh3 bar = meshes3::tetrahedral_bar(boxes, length, width);
    const Interpolation3 engine(bar, meshes3::twisted(bar, 5 * pi, length));
    for (const double t : {0.25, 0.5, 0.75}) {
      const double error = twist_error(engine.vertices_at(t), meshes3::twisted(bar, 5 * pi * t, length), width, 0, -1);
      EXPECT_LT(error, 0.35) << boxes << " boxes, t = " << t;
    }
  }
}

// One frame at a time, a batch in parallel, and one frame on two threads: the same bits. The bar has more
// elements than one exp_batched chunk, so that the two threads share its chunks.
TEST(Interpolation3, BatchFramesAreTheFramesOneAtATime) {
  const Mesh3 bar = meshes3::tetrahedral_bar(200, 20);
  const Mesh3 target = meshes3::bent(meshes3::twisted(bar, 3 * pi, 20), 20);
  ASSERT_GT(bar.element_count(), exp_chunk);
  const std::vector<double> times{0.0, 0.15, 0.5, 0.85, 1.0, 0.5};
  for (LocalHomotopy homotopy : homotopies) {
    const Interpolation3 one(bar, target, options([&](auto& o) { o.homotopy = homotopy, o.frame_threads = 1; }));
    const Interpolation3 two(bar, target, options([&](auto& o) { o.homotopy = homotopy, o.frame_threads = 2; }));
    const std::vector<Eigen::Matrix3Xd> batch = one.vertices_at(times);
    for (std::size_t f = 0; f < times.size(); ++f) {
      EXPECT_EQ(batch[f], one.vertices_at(times[f]));
      EXPECT_EQ(batch[f], two.vertices_at(times[f]));
    }
  }
}

TEST(Interpolation3, FrameTimingsArePartsOfTheFrame) {
  const Pair pair = pairs()[0];
  const Interpolation3 engine(pair.source, pair.target);
  FrameTimings timings;
  EXPECT_EQ(engine.vertices_at(0.5, timings), engine.vertices_at(0.5));
  EXPECT_GT(timings.local_maps, 0);
  EXPECT_GE(timings.right_hand_side, 0);
  EXPECT_GT(timings.solve, 0);
}

TEST(Interpolation3, RefusesANonFiniteTimeAndUnfixedTranslation) {
  const Pair pair = pairs()[0];
  const Interpolation3 engine(pair.source, pair.target);
  EXPECT_THROW(engine.vertices_at(std::nan("")), std::out_of_range);
  EXPECT_THROW(engine.vertices_at(std::vector<double>{0.5, INFINITY}), std::out_of_range);
  EXPECT_THROW(Interpolation3(pair.source, pair.target, options([](auto& o) { o.constraints = pins({}, false); })),
               affinterp::global::RefusedProblem);
  EXPECT_THROW(
      Interpolation3(pair.source, pair.target, options([](auto& o) { o.constraints = pins({pin(999, 1)}, true); })),
      affinterp::global::RefusedProblem);
  EXPECT_THROW(
      Interpolation3(pair.source, pair.target, options([](auto& o) { o.constraints = pins({pin(1, -1)}, true); })),
      affinterp::global::RefusedProblem);
}

}  // namespace interpolation3_test
