#pragma once
// Small test shapes built in the tests themselves so that they need no files (the unit square; the strip, its
// bend and its spiral from the shape pairs), and the options of `affinterp interpolate`.
#include "experiments/inputs/shapes/rolled_strip.hpp"
#include "theory/global/gauge.hpp"
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"

namespace affinterp::global::testing {

/// Two counter-clockwise triangles on the unit square: (0,1,2) and (0,2,3).
inline Mesh unit_square() {
  Mesh mesh;
  mesh.vertices.resize(2, 4);
  mesh.vertices << 0, 1, 1, 0, 0, 0, 1, 1;
  mesh.triangles.resize(3, 2);
  mesh.triangles << 0, 0, 1, 2, 2, 3;
  return mesh;
}

// The strip, its bend and its roll into a spiral: experiments/inputs/shapes/rolled_strip.hpp.
using shapes::bent;
using shapes::spiral;
using shapes::Spiral;
using shapes::strip;

/// The options of `affinterp interpolate`: area weights, the straight barycentre locus, the default gauge.
inline InterpolationOptions cli_options(Energy energy, const Spiral& s) {
  InterpolationOptions options;
  options.energy = energy;
  options.area_weighted = true;
  options.constraints.barycentre = BarycentreLocus{};
  if (const auto edge = default_edge_direction(s.source, s.target, options)) options.constraints.edges.push_back(*edge);
  return options;
}

inline double box_size(const Mesh& a, const Mesh& b) {
  Eigen::Matrix2Xd both(2, a.vertex_count() + b.vertex_count());
  both << a.vertices, b.vertices;
  return (both.rowwise().maxCoeff() - both.rowwise().minCoeff()).maxCoeff();
}

}  // namespace affinterp::global::testing
