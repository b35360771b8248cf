#pragma once
// Random compatible mesh pairs for property tests: the Delaunay triangulation of random points in the
// unit square, and a target moved by a random affine map (any rotation angle in (−π, π], scales in
// [1/2, 2], a shear) plus a random offset per vertex, shrunk until no target triangle flips.
#include "theory/global/mesh.hpp"

#include <cstdint>

namespace affinterp::shapes {

struct MeshPairShapes {
  global::Mesh source, target;
};

/// `interior_points` random points plus the square's corners; the same seed gives the same pair.
MeshPairShapes random_pair(std::uint64_t seed, int interior_points = 40);

}  // namespace affinterp::shapes
