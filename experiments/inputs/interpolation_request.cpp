#include "experiments/inputs/interpolation_request.hpp"

#include "experiments/inputs/constraint_spec.hpp"
#include "theory/global/gauge.hpp"

#include <stdexcept>

namespace affinterp::io {

global::InterpolationOptions interpolation_options(const InterpolationRequest& request, const global::Mesh& source,
                                                   const global::Mesh& target) {
  global::InterpolationOptions options;
  options.homotopy = global::parse_local_homotopy(request.local);
  options.energy = global::parse_energy(request.energy);
  if (request.rotation_branch != "consistent" && request.rotation_branch != "principal")
    throw std::invalid_argument("rotation branch '" + request.rotation_branch + "': expected consistent or principal");
  options.rotation_branch =
      request.rotation_branch == "principal" ? global::RotationBranch::principal : global::RotationBranch::consistent;
  options.blend_weight = request.blend_weight;
  options.blend_weights = request.blend_weights;
  options.area_weighted = request.area_weights;
  options.symmetric = request.symmetric;
  for (const auto& spec : request.pins) options.constraints.pinned.push_back(parse_pin(spec));
  for (const auto& spec : request.loci) options.constraints.loci.push_back(parse_locus(spec));
  for (const auto& spec : request.edges) options.constraints.edges.push_back(parse_edge_direction(spec));
  options.constraints.barycentre = parse_barycentre(request.barycentre);
  check_constraint_vertices(options.constraints, source.vertex_count());
  options.t_begin = request.t_begin, options.t_end = request.t_end;
  if (const auto edge = global::default_edge_direction(source, target, options))
    options.constraints.edges.push_back(*edge);
  return options;
}

}  // namespace affinterp::io
