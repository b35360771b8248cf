#pragma once
// The command-line syntax of the constraint terms of Kaji §4 (global::Constraints, and in 3D
// global3::Constraints3) and of per-triangle weights. Vertex indices are 0-based (the order of the `v` lines); a
// weight c > 0 follows '@'.
//   pin          V[@C]                         v_V(t) on the straight line (1−t)p_V + t q_V
//   locus        V[@C]:x1,y1;x2,y2;...        v_V(t) on the spline through the points at t = 0 … 1
//                (3D: V[@C]:x1,y1,z1;...)
//   edge         I:J[:homotopy|linear][@C]    v_I − v_J follows A_τ(t)(p_I − p_J), or the straight path (2D)
//   barycentre   linear[@C] | none | x1,y1;...[@C]   the barycentre's path (default: linear; 3D: x1,y1,z1;...)
// Errors are std::invalid_argument with a one-line message quoting the specification.
#include "theory/global/interpolation.hpp"
#include "theory/global3/constraints3.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::io {

global::PinnedVertex parse_pin(const std::string& spec);
global::VertexLocus parse_locus(const std::string& spec);
global::EdgeDirection parse_edge_direction(const std::string& spec);
/// std::nullopt for "none".
std::optional<global::BarycentreLocus> parse_barycentre(const std::string& spec);
global3::VertexLocus3 parse_locus3(const std::string& spec);
std::optional<global3::BarycentreLocus3> parse_barycentre3(const std::string& spec);
/// The 3D constraints of the specifications (pins, loci, the barycentre's), every vertex below `vertex_count`.
global3::Constraints3 parse_constraints3(const std::vector<std::string>& pins, const std::vector<std::string>& loci,
                                         const std::string& barycentre, Eigen::Index vertex_count);

/// Checks that every vertex a constraint names is below `vertex_count`.
void check_constraint_vertices(const global::Constraints& constraints, Eigen::Index vertex_count);

/// One finite number per non-empty line ('#' comments allowed); throws MeshFileError naming the line.
Eigen::VectorXd read_weights(const std::filesystem::path& file);

}  // namespace affinterp::io
