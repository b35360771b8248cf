#include "experiments/inputs/shapes/random_pair.hpp"

#include "experiments/inputs/shapes/triangulate.hpp"
#include "experiments/support/random.hpp"
#include "theory/global/mesh_validation.hpp"

#include <Eigen/Geometry>

#include <numbers>

namespace affinterp::shapes {

MeshPairShapes random_pair(std::uint64_t seed, int interior_points) {
  Rng rng(seed);
  std::vector<Eigen::Vector2d> points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < interior_points; ++k) points.emplace_back(rng.uniform(0.02, 0.98), rng.uniform(0.02, 0.98));
  MeshPairShapes pair{delaunay(points), {}};

  const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
  const Eigen::Matrix2d scale = Eigen::Vector2d(rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0)).asDiagonal();
  Eigen::Matrix2d shear = Eigen::Matrix2d::Identity();
  shear(0, 1) = rng.uniform(-0.5, 0.5);
  const Eigen::Matrix2d A = Eigen::Rotation2Dd(angle).toRotationMatrix() * shear * scale;
  const Eigen::Vector2d d(rng.uniform(-1, 1), rng.uniform(-1, 1));
  Eigen::Matrix2Xd offsets(2, pair.source.vertex_count());
  for (Eigen::Index k = 0; k < offsets.cols(); ++k)
    offsets.col(k) = Eigen::Vector2d(rng.uniform(-1, 1), rng.uniform(-1, 1));

  const Eigen::Matrix2Xd moved = (A * pair.source.vertices).colwise() + d;
  pair.target = pair.source;
  for (double amplitude = 0.3 / std::sqrt(interior_points + 4.0);; amplitude /= 2) {
    pair.target.vertices = moved + amplitude * offsets;
    if (global::flipped_triangles(pair.target).empty()) break;
  }
  return pair;
}

}  // namespace affinterp::shapes
