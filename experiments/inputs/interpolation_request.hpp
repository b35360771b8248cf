#pragma once
// What a caller of the global interpolation (Kaji §4) asks for, in the words of the `affinterp interpolate`
// options, with their defaults: the one place the CLI and the Python module turn a request into the
// engine's InterpolationOptions, so that both give the same vertices for the same input.
//   local homotopy A_i(t) (Kaji §3): exp (eq. 3), polar (eq. 2), linear, svd
//   energy E_i: F, S, R (eq. 4), blend;  area weights;  symmetrisation — each defaulting as the engine does
//   constraints C: the syntax of constraint_spec.hpp; the barycentre follows the straight line by default,
//   and with E^S, E^R or a blend and no vertex or edge constraint one edge fixes rotation and scale
//   (theory/global/gauge.hpp)
#include "theory/global/interpolation.hpp"

#include <string>
#include <vector>

namespace affinterp::io {

/// Every default is the engine's (global::InterpolationOptions{}): one place decides it, the CLI and Python read it.
struct InterpolationRequest {
  std::string local = global::to_string(global::InterpolationOptions{}.homotopy),
              energy = global::to_string(global::InterpolationOptions{}.energy),
              rotation_branch = global::to_string(global::InterpolationOptions{}.rotation_branch);
  double blend_weight = global::InterpolationOptions{}.blend_weight;
  Eigen::VectorXd blend_weights;  ///< w_i per triangle; empty: blend_weight for every triangle
  bool area_weights = global::InterpolationOptions{}.area_weighted,
       symmetric = global::InterpolationOptions{}.symmetric;
  std::vector<std::string> pins, loci, edges;
  /// The gauge of translation: a request's choice, as the engine's Constraints are what its caller asks for.
  std::string barycentre = "linear";
  double t_begin = global::InterpolationOptions{}.t_begin, t_end = global::InterpolationOptions{}.t_end;
};

/// The engine's options for the pair (source counter-clockwise, as check_mesh_pair leaves it), the default
/// edge direction included (last in constraints.edges). Throws std::invalid_argument with a one-line message
/// on a bad name or constraint.
global::InterpolationOptions interpolation_options(const InterpolationRequest& request, const global::Mesh& source,
                                                   const global::Mesh& target);

}  // namespace affinterp::io
