#pragma once
// What a caller of the global interpolation (Kaji §4) asks for, in the words of the `affinterp interpolate`
// options, with their defaults: the one place the CLI and the Python module turn a request into the
// engine's InterpolationOptions, so that both give the same vertices for the same input.
//   local homotopy A_i(t) (Kaji §3): exp (eq. 3, the default), polar (eq. 2), linear, svd
//   energy E_i: F, S, R (eq. 4, the default), blend;  area weights on;  not symmetrised
//   constraints C: the syntax of constraint_spec.hpp; the barycentre follows the straight line by default,
//   and with E^S, E^R or a blend and no vertex or edge constraint one edge fixes rotation and scale
//   (theory/global/gauge.hpp)
#include "theory/global/interpolation.hpp"

#include <string>
#include <vector>

namespace affinterp::io {

struct InterpolationRequest {
  std::string local = "exp", energy = "R", rotation_branch = "consistent";
  double blend_weight = 0.5;
  Eigen::VectorXd blend_weights;  ///< w_i per triangle; empty: blend_weight for every triangle
  bool area_weights = true, symmetric = false;
  std::vector<std::string> pins, loci, edges;
  std::string barycentre = "linear";
  double t_begin = 0.0, t_end = 1.0;  ///< the times the engine accepts
};

/// The engine's options for the pair (source counter-clockwise, as check_mesh_pair leaves it), the default
/// edge direction included (last in constraints.edges). Throws std::invalid_argument with a one-line message
/// on a bad name or constraint.
global::InterpolationOptions interpolation_options(const InterpolationRequest& request, const global::Mesh& source,
                                                   const global::Mesh& target);

}  // namespace affinterp::io
