#pragma once
// Outlines of the two triangles of the origin study, as polylines for the plotter.
#include "plots/figure.hpp"
#include "theory/origin/two_triangles.hpp"

#include <Eigen/Core>

namespace affinterp::plots {

/// Triangle i of `config` with vertices `v` (columns), as a closed polyline.
Table triangle_outline(const origin::TwoTriangles& config, unsigned i, const Eigen::Matrix<double, 2, 4>& v);

/// The source vertices of `config` as doubles.
Eigen::Matrix<double, 2, 4> source_vertices(const origin::TwoTriangles& config);

}  // namespace affinterp::plots
