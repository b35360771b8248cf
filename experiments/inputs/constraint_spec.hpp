#pragma once
// The command-line syntax of the constraint terms of Kaji §4 (global::Constraints) and of per-triangle
// weights. Vertex indices are 0-based (the order of the `v` lines); a weight c > 0 follows '@'.
//   pin          V[@C]                         v_V(t) on the straight line (1−t)p_V + t q_V
//   locus        V[@C]:x1,y1;x2,y2;...        v_V(t) on the spline through the points at t = 0 … 1
//   edge         I:J[:homotopy|linear][@C]    v_I − v_J follows A_τ(t)(p_I − p_J), or the straight path
//   barycentre   linear[@C] | none | x1,y1;...[@C]   the barycentre's path (default: linear)
// Errors are std::invalid_argument with a one-line message quoting the specification.
#include "theory/global/interpolation.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace affinterp::io {

global::PinnedVertex parse_pin(const std::string& spec);
global::VertexLocus parse_locus(const std::string& spec);
global::EdgeDirection parse_edge_direction(const std::string& spec);
/// std::nullopt for "none".
std::optional<global::BarycentreLocus> parse_barycentre(const std::string& spec);

/// Checks that every vertex a constraint names is below `vertex_count`.
void check_constraint_vertices(const global::Constraints& constraints, Eigen::Index vertex_count);

/// One finite number per non-empty line ('#' comments allowed); throws MeshFileError naming the line.
Eigen::VectorXd read_weights(const std::filesystem::path& file);

}  // namespace affinterp::io
