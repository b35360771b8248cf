#pragma once
// 1-to-4 subdivision of a compatible pair: every edge gets its midpoint, in the source and in the target,
// and every triangle (a, b, c) becomes (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca). Both meshes stay
// compatible and counter-clockwise, the triangle count grows fourfold, and each new triangle has its
// parent's linear part A_i (eq. (1)): the same deformation on a finer mesh, for the scale benchmark.
#include "experiments/inputs/shapes/random_pair.hpp"

namespace affinterp::shapes {

/// The pair subdivided once: vertices first as given, then one midpoint per edge.
MeshPairShapes subdivided(const MeshPairShapes& pair);

}  // namespace affinterp::shapes
