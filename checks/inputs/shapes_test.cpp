// The generated shape pairs: deterministic, compatible, well-shaped, targets unflipped; the worm's curl
// matches its stated geometry; filmstrips draw.
#include "experiments/inputs/shapes/catalogue.hpp"
#include "experiments/inputs/shapes/man.hpp"
#include "experiments/inputs/shapes/subdivide.hpp"
#include "plots/mesh_strip.hpp"
#include "theory/global/mesh_validation.hpp"
#include "theory/global/metrics.hpp"
#include "theory/global/triangle_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

namespace shapes_test {

namespace {

namespace fs = std::filesystem;
using namespace affinterp;

double smallest_angle(const global::Mesh& mesh) {
  double smallest = std::numbers::pi;
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector2d a = mesh.corner(i, (c + 1) % 3) - mesh.corner(i, c),
                            b = mesh.corner(i, (c + 2) % 3) - mesh.corner(i, c);
      smallest = std::min(smallest, std::acos(std::clamp(a.dot(b) / a.norm() / b.norm(), -1.0, 1.0)));
    }
  return smallest;
}

TEST(Shapes, EveryPairIsAValidCompatibleInput) {
  for (const auto& info : shapes::shape_catalogue()) {
    SCOPED_TRACE(info.name);
    auto pair = shapes::make_shape(info.name);
    EXPECT_NO_THROW(global::check_well_formed(pair.source));
    EXPECT_NO_THROW(global::check_well_formed(pair.target));
    EXPECT_NO_THROW(global::check_compatible(pair.source, pair.target));
    EXPECT_FALSE(global::orient_counter_clockwise(pair.source)) << "generated triangles run counter-clockwise";
    EXPECT_TRUE(global::flipped_triangles(pair.target).empty());
    EXPECT_GT(pair.source.triangle_count(), 40);
  }
}

TEST(Shapes, SubdivisionQuadruplesTheTrianglesAndKeepsEachLinearPart) {
  const auto pair = shapes::make_shape("man-wave");
  auto fine = shapes::subdivided(pair);
  EXPECT_NO_THROW(global::check_well_formed(fine.source));
  EXPECT_NO_THROW(global::check_compatible(fine.source, fine.target));
  EXPECT_NO_THROW(global::check_connected(fine.source));
  EXPECT_FALSE(global::orient_counter_clockwise(fine.source));
  EXPECT_TRUE(global::flipped_triangles(fine.target).empty());
  ASSERT_EQ(fine.source.triangle_count(), 4 * pair.source.triangle_count());
  std::set<std::pair<int, int>> edges;  // one midpoint each
  for (Eigen::Index i = 0; i < pair.source.triangle_count(); ++i)
    for (int c = 0; c < 3; ++c)
      edges.insert(std::minmax(pair.source.triangles(c, i), pair.source.triangles((c + 1) % 3, i)));
  EXPECT_EQ(fine.source.vertex_count(), pair.source.vertex_count() + static_cast<Eigen::Index>(edges.size()));
  for (Eigen::Index i = 0; i < pair.source.triangle_count(); ++i) {
    global::Corners<double> p, q;
    for (int c = 0; c < 3; ++c) p.col(c) = pair.source.corner(i, c), q.col(c) = pair.target.corner(i, c);
    const Eigen::Matrix2d A = global::linear_part(p, q);
    double area = 0;
    for (Eigen::Index child = 4 * i; child < 4 * i + 4; ++child) {
      for (int c = 0; c < 3; ++c) p.col(c) = fine.source.corner(child, c), q.col(c) = fine.target.corner(child, c);
      EXPECT_LT((global::linear_part(p, q) - A).norm(), 1e-9 * A.norm());
      area += fine.source.doubled_signed_area(child);
    }
    EXPECT_NEAR(area, pair.source.doubled_signed_area(i), 1e-12);
  }
}

TEST(Shapes, MeshedOutlinesHaveNoSmallAngles) {
  for (const std::string name : {"man-wave", "worm-curl", "graded-bend"})
    EXPECT_GT(smallest_angle(shapes::make_shape(name).source), 20.0 * std::numbers::pi / 180) << name;
}

TEST(Shapes, AreDeterministic) {
  for (const auto& info : shapes::shape_catalogue()) {
    const auto a = shapes::make_shape(info.name, 7), b = shapes::make_shape(info.name, 7);
    EXPECT_EQ(a.source.vertices, b.source.vertices) << info.name;
    EXPECT_EQ(a.source.triangles, b.source.triangles) << info.name;
    EXPECT_EQ(a.target.vertices, b.target.vertices) << info.name;
  }
  EXPECT_NE(shapes::make_shape("random", 1).target.vertices, shapes::make_shape("random", 2).target.vertices);
}

TEST(Shapes, UnknownNameIsRefused) { EXPECT_THROW(shapes::make_shape("teapot"), std::invalid_argument); }

TEST(Shapes, WormCurlKeepsTheCentreLineLengthAndTurnsTheEndByThreePi) {
  const shapes::Curl& curl = shapes::worm_curl();
  EXPECT_NEAR(curl.theta_end, 3 * std::numbers::pi, 1e-15);
  // Arc length of the curled centre line, by fine polyline: L.
  double length = 0;
  Eigen::Vector2d previous = curl.apply(Eigen::Vector2d(0, 0), 1);
  for (int j = 1; j <= 4000; ++j) {
    const Eigen::Vector2d next = curl.apply(Eigen::Vector2d(curl.length * j / 4000, 0), 1);
    length += (next - previous).norm();
    previous = next;
  }
  EXPECT_NEAR(length, curl.length, 1e-5);
  // The end's cross-section is turned by t·θ_end: its direction (the image of (L, ±h)) is n_t(L).
  for (double t : {0.0, 0.5, 1.0}) {
    const Eigen::Vector2d d =
        curl.apply(Eigen::Vector2d(curl.length, 0.1), t) - curl.apply(Eigen::Vector2d(curl.length, -0.1), t);
    const double angle = t * curl.theta_end;
    EXPECT_NEAR(d.x(), -0.2 * std::sin(angle), 1e-12);
    EXPECT_NEAR(d.y(), 0.2 * std::cos(angle), 1e-12);
  }
  // Each source triangle's map is a rotation by ≈ θ(s) (up to the bending stretch across the width).
  const auto pair = shapes::make_shape("worm-curl");
  // The inner side at the end is compressed by 1 − (h/2)κ(L), κ = θ' = 2θ_end/L: the largest σ1/σ2.
  const global::FrameMetrics m = global::frame_metrics(pair.source, pair.target.vertices);
  const double compression = 1 - 0.25 * 2 * curl.theta_end / curl.length;
  EXPECT_EQ(m.flipped_triangles, 0);
  EXPECT_LT(m.max_distortion, 1.01 / compression);
  EXPECT_GT(m.max_distortion, 0.9 / compression);
}

TEST(Shapes, ManPosesMoveTheLimbsNotTheTorso) {
  const global::Mesh rest = shapes::man();
  for (const auto& pose : shapes::man_poses()) {
    const Eigen::Matrix2Xd posed = shapes::pose_vertices(rest.vertices, pose);
    for (Eigen::Index k = 0; k < rest.vertex_count(); ++k) {  // the belly, far from every joint, stays
      const Eigen::Vector2d p = rest.vertices.col(k);
      if (std::abs(p.x()) < 0.1 && std::abs(p.y() - 0.6) < 0.1) {
        EXPECT_EQ(posed.col(k), p);
      }
    }
  }
}

TEST(Shapes, FilmstripsDraw) {
  const fs::path folder = fs::temp_directory_path() / "affinterp_shapes_test";
  fs::create_directories(folder);
  for (const std::string name : {"man-twirl", "random"}) {
    const auto pair = shapes::make_shape(name);
    const auto files =
        plots::draw_filmstrip(folder / name, pair.source.triangles,
                              {{pair.source.vertices, "source"}, {pair.target.vertices, "target"}}, name);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_GT(fs::file_size(folder / (name + ".png")), 1000u);
  }
}

}  // namespace

}  // namespace shapes_test
