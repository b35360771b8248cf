#pragma once
// A request for the global interpolation of Kaji §4 as the CLI (`affinterp interpolate`) and the Python module
// (affinterp.Interpolation) take it: the engine's own InterpolationOptions, whose defaults, names
// (theory/global/options.hpp's tables) and rules (global::require_valid_options) are the engine's, and the
// constraints C in their textual syntax (constraint_spec.hpp). Both front ends turn a request into the engine's
// options here, so that both give the same vertices for the same input, and describe it in the same words
// (metrics.json's "options").
#include "theory/global/interpolation.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace affinterp::io {

struct InterpolationRequest {
  /// Everything but the constraints, defaults included. Its `constraints` are replaced by the ones below.
  global::InterpolationOptions options;
  /// Constraint specifications (constraint_spec.hpp), one per term.
  std::vector<std::string> pins, loci, edge_directions;
  /// The barycentre's path: the gauge of translation, "linear" (source to target) unless asked otherwise.
  std::string barycentre_locus = "linear";
  /// 3D only: as-rigid-as-possible steps on each frame (global3::Interpolation3Options::arap_iterations). The 2D
  /// engine has E^R itself and refuses a request that sets it.
  int arap_iterations = 0;
};

/// The engine's options for the pair (source counter-clockwise, as check_mesh_pair leaves it): the request's
/// options with its constraints parsed, and with E^S, E^R or a blend and no vertex or edge constraint the
/// default edge direction that fixes rotation and scale (theory/global/gauge.hpp), last in constraints.edges.
/// Throws std::invalid_argument with a one-line message on a bad constraint; the options themselves are the
/// engine's to check (global::Interpolation refuses them).
global::InterpolationOptions interpolation_options(const InterpolationRequest& request, const global::Mesh& source,
                                                   const global::Mesh& target);

/// The options a run used, as metrics.json's "options" names them (the same names as the CLI's options and
/// the Python keywords): homotopy, energy, rotation_branch, blend_weight, area_weighted, symmetric, pins,
/// loci, edge_directions, barycentre_locus, time_range, arap_iterations, and default_edge_direction when one was
/// added.
nlohmann::json options_json(const InterpolationRequest& request, const global::InterpolationOptions& used);

}  // namespace affinterp::io
