#include "experiments/claims/claim.hpp"
#include "experiments/claims/global3/figures3.hpp"
#include "experiments/inputs/shapes3d/bar3.hpp"
#include "experiments/inputs/shapes3d/demo_poses.hpp"
#include "experiments/inputs/shapes3d/tetrahedralised.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/local3/svd3.hpp"

#include <boost/multiprecision/cpp_int.hpp>  // cpp_rational

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace affinterp::claims::sequel_3d_exp_log_never_inverts {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "sequel.3d.exp-log-never-inverts",
    .chapter = Chapter::global3,
    .where = "Kaji §3 (eq. 3) carried to 3×3 maps",
    .statement =
        "The exp-log homotopy A(t) = R^t S^t of a 3×3 map with det A > 0 never inverts: det A(t) = e^{t tr log S} > 0 "
        "for every t; the linear homotopy (1 − t)I + tA can reach det 0 inside (0, 1).",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: in 3D as in 2D (kaji.exp.det-positive), det R^t = 1 and det S^t = e^{t tr log S}. The polar homotopy
//   R^t((1 − t)I + tS) cannot invert either (S ≻ 0, so (1 − t)I + tS ≻ 0 on [0, 1]): the counterexample is the
//   linear homotopy's only.
// Method: every element's local map A_i(t) of Interpolation3 (exp-log, consistent branch) on a capsule of
//   tetrahedra meshed by CGAL's Mesh_3 (length 6, radius 1/2, cells of about 1/4: tetrahedralised.hpp) towards its
//   twist by 1.5π, on the project's elephant poses (CGAL's elephant.off, rest → bent, rest → twisted:
//   experiments/inputs/shapes3d/demo_poses.hpp) and, when ../shared/data has them, the cat poses cat-0 → cat-4 and
//   cat-0 → cat-7 (Sumner and Popović 2004), at each grid t: det A_i(t) > 0 and |det A_i(t) / e^{t tr log S_i} − 1| ≤
//   10⁻⁹. The linear homotopy's counterexample is exact: A = diag(−1, −1, 1), a half turn, det((1 − t)I + tA) = (1 −
//   2t)² = 0 at t = 1/2, in integers.
// Sizes: quick t ∈ {1/4, 1/2, 3/4}; full t = 0.1, 0.2, …, 0.9; every element of each pair (no random draw: the
//   grid is the listed pairs times these t).

constexpr double tolerance = 1e-9;

struct Tally {
  std::uint64_t maps = 0, inverted = 0;
  double worst = 0;  ///< max |det A_i(t) / e^{t tr log S_i} − 1|
};

/// det A_i(t) against e^{t tr log S_i} for every element of the pair, at each grid t.
void tally_pair(const global3::Mesh3& source, const global3::Mesh3& target, int steps, Tally& tally) {
  const global3::Interpolation3 engine(source, target);
  const std::vector<Eigen::Matrix3d> ends = engine.local_maps_at(1);
  std::vector<double> trace_log_s(ends.size());
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const local3::Svd3<double> d = local3::svd3<double>(ends[i]);
    trace_log_s[i] = d.sigma.array().log().sum();  // tr log S = Σ log σ_j
  }
  for (int k = 1; k < steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    const std::vector<Eigen::Matrix3d> maps = engine.local_maps_at(t);
    for (std::size_t i = 0; i < maps.size(); ++i) {
      const double det = maps[i].determinant();
      tally.maps += 1;
      tally.inverted += det <= 0 ? 1 : 0;
      tally.worst = std::max(tally.worst, std::abs(det / std::exp(t * trace_log_s[i]) - 1));
    }
  }
}

/// det((1 − t)I + tA) at t = 1/2 for the half turn A = diag(−1, −1, 1) about z, in exact rationals (the rule of
/// Sarrus on the full matrix): 0, an inverted in-between map.
bool linear_half_turn_inverts() {
  using Q = boost::multiprecision::cpp_rational;
  const int A[3][3] = {{-1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
  const Q t(1, 2);
  Q M[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M[r][c] = (r == c ? 1 - t : Q(0)) + t * A[r][c];
  const Q det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  return det == 0;
}

std::vector<std::pair<std::string, std::pair<global3::Mesh3, global3::Mesh3>>> pairs() {
  std::vector<std::pair<std::string, std::pair<global3::Mesh3, global3::Mesh3>>> out;
  const global3::Mesh3 capsule = shapes3d::tetrahedralised_capsule(6, 0.25);
  out.push_back(
      {"Mesh_3 capsule -> twisted by 1.5 pi", {capsule, shapes3d::twisted(capsule, 1.5 * std::numbers::pi, 6)}});
  if (const auto e = shapes3d::elephant_poses(global3_figures::demo_folder())) {
    out.push_back({"elephant rest -> bent", {(*e)[0], (*e)[1]}});
    out.push_back({"elephant rest -> twisted", {(*e)[0], (*e)[2]}});
  }
  if (const auto cat = shapes3d::cat_poses({0, 4, 7})) {
    out.push_back({"cat-0 -> cat-4", {(*cat)[0], (*cat)[1]}});
    out.push_back({"cat-0 -> cat-7", {(*cat)[0], (*cat)[2]}});
  }
  return out;
}

std::vector<std::string> draw(const ClaimContext& ctx) {
  const auto cat = shapes3d::cat_poses({0, 4});
  const auto poses = cat ? cat : shapes3d::elephant_poses(global3_figures::demo_folder());
  if (!poses) return {};
  const global3::Interpolation3 engine(poses->front(), poses->back());
  const std::string title = cat ? "cat-0 to cat-4 (Sumner and Popović 2004), exp-log E^F"
                                : "CGAL's elephant, rest to twisted by π per length, exp-log E^F";
  return RunSettings::figure_refs(
      global3_figures::interpolation_filmstrip(ctx.figure_stem("sequel-3d-filmstrip"), poses->front(), engine, title));
}

Outcome check(const ClaimContext& ctx) {
  Outcome out;
  const auto sample = pairs();
  if (sample.empty()) {
    out.verdict = Verdict::inconclusive;
    out.summary = "neither CGAL's demo meshes (libcgal-demo) nor the cat poses are present";
    return out;
  }
  const int steps = ctx.pick(4, 10);
  Tally tally;
  nlohmann::json names = nlohmann::json::array();
  for (const auto& [name, pair] : sample) tally_pair(pair.first, pair.second, steps, tally), names.push_back(name);
  const bool linear_inverts = linear_half_turn_inverts();
  const bool holds = tally.inverted == 0 && tally.worst <= tolerance && linear_inverts;
  out.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  char line[320];
  std::snprintf(line, sizeof line,
                "%llu exp-log local maps A_i(t) (%zu pose pairs, %d times): %llu with det <= 0, det / e^{t tr log S} "
                "within %.1e of 1; linear: the half turn diag(−1, −1, 1) has det((1 − t)I + tA) = 0 at t = 1/2",
                static_cast<unsigned long long>(tally.maps), sample.size(), steps - 1,
                static_cast<unsigned long long>(tally.inverted), tally.worst);
  out.summary = line;
  if (!holds) out.counterexample = {{"inverted", tally.inverted}, {"worst", tally.worst}};
  out.evidence.method =
      "det of every element's exp-log local map (Interpolation3::local_maps_at) on the listed pose pairs at each grid "
      "t, against e^{t tr log S_i} (tr log S_i = Σ log σ_j from svd3); the cat poses are Sumner and Popović's "
      "(SIGGRAPH 2004); linear counterexample in exact rationals";
  out.evidence.sample_size = tally.maps;
  out.evidence.tolerance = tolerance;
  out.evidence.worst_deviation = tally.worst;
  out.evidence.details = {{"pairs", names}, {"linear_counterexample", "A = diag(-1, -1, 1), t = 1/2"}};
  if (ctx.draws_figures()) out.figures = draw(ctx);
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sequel_3d_exp_log_never_inverts
