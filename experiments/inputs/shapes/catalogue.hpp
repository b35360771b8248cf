#pragma once
// The project's generated shape pairs: deterministic source/target meshes with one triangle list, the
// default inputs of `affinterp interpolate` and of the global-interpolation checks (../shared is not
// available to users).
#include "experiments/inputs/shapes/curl.hpp"
#include "experiments/inputs/shapes/random_pair.hpp"
#include "experiments/inputs/shapes/rolled_strip.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace affinterp::shapes {

struct ShapeInfo {
  std::string name;
  std::string description;
};

/// Every shape pair's name and a one-line description.
const std::vector<ShapeInfo>& shape_catalogue();

/// The named pair (`seed` matters only for "random", `quads` only for "strip-spiral"); throws
/// std::invalid_argument for an unknown name.
MeshPairShapes make_shape(const std::string& name, std::uint64_t seed = 1, StripQuads quads = {});

/// The worm: a bar 8 × 0.5 and its curl whose end turns by 3π (θ(s) = 3π (s/L)²).
const Curl& worm_curl();
/// The graded bar: a bar 4 × 1 meshed finely for x < 1.5 and coarsely elsewhere.
global::Mesh graded_bar();
/// Its target: tapered (width × (1 − 0.4 x/L)) then bent into a quarter circle (θ(s) = (π/2) s/L).
Eigen::Matrix2Xd graded_bar_target(const Eigen::Matrix2Xd& rest);

}  // namespace affinterp::shapes
