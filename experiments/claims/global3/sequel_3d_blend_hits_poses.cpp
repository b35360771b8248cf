#include "experiments/claims/claim.hpp"
#include "experiments/claims/global3/figures3.hpp"
#include "experiments/inputs/shapes3d/bar3.hpp"
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "experiments/inputs/shapes3d/tetrahedralised.hpp"
#include "theory/global3/blend3.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>

namespace affinterp::claims::sequel_3d_blend_hits_poses {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "sequel.3d.blend-hits-poses",
    .chapter = Chapter::global3,
    .where = "Kaji et al.'s Lie-algebra blend (the thesis's reference [6]) with the global solve of Kaji §4, in 3D",
    .statement = "The N-way blend A_i(w) = exp(Σ_k w_k [ω_{k,i}]×) exp(Σ_k w_k log S_{k,i}) followed by E^F's solve "
                 "gives pose k exactly at the weights w = e_k (up to rounding).",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: at w = e_k the maps are pose k's own (exp of its logarithms), which pose k's vertices fit with E^F = 0,
//   and the barycentre constraint puts them where pose k is.
// Method: Blend3 (rest = pose 0) on three pose sets: a bar of tetrahedra (length 10, width 1/10, 30 boxes) with
//   its twist by 1.8π and its bend, an open tube of triangles twisted by 1.5π and bent
//   (experiments/inputs/shapes3d/bar3.hpp), a capsule of tetrahedra meshed by CGAL's Mesh_3 with the same twist and
//   bend (tetrahedralised.hpp), and CGAL's elephant.off rest, bent, twisted (demo_poses.hpp) when
//   libcgal-demo is installed; max over vertices of |v(e_k) − pose k| / the pose's bounding-box diagonal ≤ 10⁻⁹.
// Sizes: every pose of each set (the unit weights are the grid); the same at either size.

constexpr double tolerance = 1e-9;

double box_diagonal(const Eigen::Matrix3Xd& v) { return (v.rowwise().maxCoeff() - v.rowwise().minCoeff()).norm(); }

std::vector<std::pair<std::string, std::vector<global3::Mesh3>>> pose_sets() {
  const double pi = std::numbers::pi;
  const global3::Mesh3 bar = shapes3d::tetrahedral_bar(30, 10, 0.1), tube = shapes3d::triangle_tube(12, 10, 4);
  std::vector<std::pair<std::string, std::vector<global3::Mesh3>>> sets{
      {"bar", {bar, shapes3d::twisted(bar, 1.8 * pi, 10), shapes3d::bent(bar, 10)}},
      {"tube", {tube, shapes3d::twisted(tube, 1.5 * pi, 4), shapes3d::bent(tube, 4)}}};
  const global3::Mesh3 capsule = shapes3d::tetrahedralised_capsule(6, 0.25);
  sets.push_back({"Mesh_3 capsule", {capsule, shapes3d::twisted(capsule, 1.5 * pi, 6), shapes3d::bent(capsule, 6)}});
  if (auto elephant = shapes3d::elephant_poses(global3_figures::demo_folder()))
    sets.push_back({"elephant", std::move(*elephant)});
  return sets;
}

Outcome check(const ClaimContext& ctx) {
  double worst = 0;
  std::string worst_at;
  std::uint64_t poses = 0;
  nlohmann::json names = nlohmann::json::array();
  const auto sets = pose_sets();
  for (const auto& [name, set] : sets) {
    const global3::Blend3 blend(set);
    names.push_back(name);
    for (std::size_t k = 0; k < set.size(); ++k, ++poses) {
      const Eigen::VectorXd w =
          Eigen::VectorXd::Unit(static_cast<Eigen::Index>(set.size()), static_cast<Eigen::Index>(k));
      const double error =
          (blend.vertices_at(w) - set[k].vertices).colwise().norm().maxCoeff() / box_diagonal(set[k].vertices);
      if (error > worst) worst = error, worst_at = name + " pose " + std::to_string(k);
    }
  }
  Outcome out;
  out.verdict = worst <= tolerance ? Verdict::confirmed : Verdict::refuted;
  char line[200];
  std::snprintf(line, sizeof line, "w = e_k gives pose k within %.1e of its box diagonal (worst: %s) on %d poses",
                worst, worst_at.c_str(), static_cast<int>(poses));
  out.summary = line;
  if (out.verdict == Verdict::refuted) out.counterexample = {{"at", worst_at}, {"relative_error", worst}};
  out.evidence.method = "Blend3 (rest = pose 0, consistent branches, E^F) at each unit weight vector against the pose";
  out.evidence.sample_size = poses;
  out.evidence.tolerance = tolerance;
  out.evidence.worst_deviation = worst;
  out.evidence.details = {{"pose_sets", names}};
  if (ctx.draws_figures() && sets.back().first == "elephant")
    out.figures = RunSettings::figure_refs(global3_figures::blend_triangle(
        ctx.figure_stem("sequel-3d-blend-triangle"), sets.back().second, {"rest", "bent", "twisted"},
        "CGAL's elephant: N-way blend of three poses at weights (i, j, k)/3"));
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sequel_3d_blend_hits_poses
