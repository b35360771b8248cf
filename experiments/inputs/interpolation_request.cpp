#include "experiments/inputs/interpolation_request.hpp"

#include "experiments/inputs/constraint_spec.hpp"
#include "theory/global/gauge.hpp"

namespace affinterp::io {

global::InterpolationOptions interpolation_options(const InterpolationRequest& request, const global::Mesh& source,
                                                   const global::Mesh& target) {
  global::InterpolationOptions options = request.options;
  options.constraints = {};
  for (const auto& spec : request.pins) options.constraints.pinned.push_back(parse_pin(spec));
  for (const auto& spec : request.loci) options.constraints.loci.push_back(parse_locus(spec));
  for (const auto& spec : request.edge_directions) options.constraints.edges.push_back(parse_edge_direction(spec));
  options.constraints.barycentre = parse_barycentre(request.barycentre_locus);
  check_constraint_vertices(options.constraints, source.vertex_count());
  if (const auto edge = global::default_edge_direction(source, target, options))
    options.constraints.edges.push_back(*edge);
  return options;
}

nlohmann::json options_json(const InterpolationRequest& request, const global::InterpolationOptions& used) {
  nlohmann::json json = {{"homotopy", global::to_string(used.homotopy)},
                         {"energy", global::to_string(used.energy)},
                         {"rotation_branch", global::to_string(used.rotation_branch)},
                         {"blend_weight", used.blend_weight},
                         {"area_weighted", used.area_weighted},
                         {"symmetric", used.symmetric},
                         {"pins", request.pins},
                         {"loci", request.loci},
                         {"edge_directions", request.edge_directions},
                         {"barycentre_locus", request.barycentre_locus},
                         {"time_range", {used.t_begin, used.t_end}},
                         {"arap_iterations", request.arap_iterations}};
  if (used.constraints.edges.size() > request.edge_directions.size()) {
    const global::EdgeDirection& edge = used.constraints.edges.back();
    json["default_edge_direction"] = std::to_string(edge.i) + ":" + std::to_string(edge.j);
  }
  return json;
}

}  // namespace affinterp::io
