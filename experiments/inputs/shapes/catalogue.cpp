#include "experiments/inputs/shapes/catalogue.hpp"

#include "experiments/inputs/shapes/man.hpp"
#include "experiments/inputs/shapes/triangulate.hpp"

#include <numbers>
#include <stdexcept>
#include <utility>

namespace affinterp::shapes {

namespace {

using std::numbers::pi;

Outline rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

constexpr double worm_length = 8, worm_width = 0.5;
constexpr double bar_length = 4, bar_width = 1, fine_end = 1.5;

}  // namespace

const Curl& worm_curl() {
  static const Curl curl{worm_length, 3 * pi, 2};
  return curl;
}

global::Mesh graded_bar() {
  std::vector<Eigen::Vector2d> fine;  // a lattice with spacing 0.05 strictly inside the fine part
  for (int i = 1; i < 30; ++i)
    for (int j = 1; j < 20; ++j) fine.emplace_back(0.05 * i, -bar_width / 2 + 0.05 * j);
  return triangulate(rectangle(0, -bar_width / 2, bar_length, bar_width / 2), 0.4, fine);
}

Eigen::Matrix2Xd graded_bar_target(const Eigen::Matrix2Xd& rest) {
  Eigen::Matrix2Xd tapered = rest;
  tapered.row(1).array() *= 1 - 0.4 * rest.row(0).array() / bar_length;
  return Curl{bar_length, pi / 2, 1}.apply(tapered, 1);
}

const std::vector<ShapeInfo>& shape_catalogue() {
  static const std::vector<ShapeInfo> list = [] {
    std::vector<ShapeInfo> shapes;
    for (const Pose& pose : man_poses())
      shapes.push_back(
          {"man-" + pose.name, "gingerbread man, rest pose -> '" + pose.name +
                                   "' (skeletal deformation: limbs rotated about joints, smoothly blended)"});
    shapes.push_back({"worm-curl", "bar 8 x 0.5 -> curled so the end turns by 3*pi (exact in-between poses known)"});
    shapes.push_back(
        {"graded-bend", "bar 4 x 1, fine triangles for x < 1.5, coarse elsewhere -> tapered and bent by pi/2"});
    shapes.push_back({"strip-spiral",
                      "strip 18.8 x 2 of 2000 x 250 quads (1,000,000 triangles) -> rolled 1.5 turns "
                      "(the engine's scale case; 40 MB as OBJ)"});
    shapes.push_back(
        {"random", "Delaunay mesh of random points -> random affine map plus per-vertex offsets (--seed)"});
    return shapes;
  }();
  return list;
}

MeshPairShapes make_shape(const std::string& name, std::uint64_t seed, StripQuads quads) {
  for (const Pose& pose : man_poses())
    if (name == "man-" + pose.name) {
      MeshPairShapes pair{man(), {}};
      pair.target = pair.source;
      pair.target.vertices = pose_vertices(pair.source.vertices, pose);
      return pair;
    }
  if (name == "worm-curl") {
    MeshPairShapes pair{triangulate(rectangle(0, -worm_width / 2, worm_length, worm_width / 2), 0.12), {}};
    pair.target = pair.source;
    pair.target.vertices = worm_curl().apply(pair.source.vertices, 1);
    return pair;
  }
  if (name == "graded-bend") {
    MeshPairShapes pair{graded_bar(), {}};
    pair.target = pair.source;
    pair.target.vertices = graded_bar_target(pair.source.vertices);
    return pair;
  }
  if (name == "strip-spiral") {
    Spiral s = spiral(quads.cols, quads.rows);
    return {std::move(s.source), std::move(s.target)};
  }
  if (name == "random") return random_pair(seed);
  throw std::invalid_argument("unknown shape '" + name + "' (see --list)");
}

}  // namespace affinterp::shapes
