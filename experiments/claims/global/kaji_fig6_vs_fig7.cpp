#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/animation.hpp"
#include "experiments/claims/global/figure_setups.hpp"
#include "experiments/inputs/shapes/catalogue.hpp"
#include "theory/global/local_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::claims::kaji_fig6_vs_fig7 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.fig6-vs-fig7",
    .chapter = Chapter::global,
    .where = "Kaji Figs 6, 7",
    .statement = "Weighting E^R by triangle area keeps large triangles more rigid than unweighted E^R.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: "more rigid" = closer to the local homotopy up to similarity, which is what E^R measures: the mean of
//   E^R(A_i(t), B_i(t))/‖B_i(t)‖² over interior frames.
// Method: the generated graded bar (fine at one end, coarse at the other, bent by π/2), both base vertices pinned,
//   under two pushes of its far corners (stretch, widen); E^R unweighted against E^R with E_i ← Area_i E_i, the
//   constraint weights scaled by the mean area so that only the distribution over triangles changes. The large
//   triangles (area ≥ ¼ of the largest) must deviate less when weighted.
// Sizes: quick 7 frames; full 21.

using global::Energy;
using global::InterpolationOptions;
using global::Mesh;
using namespace global_figures;

/// Shape deviation of B from A up to similarity, scale-free: E^R(A, B)/‖B‖².
double shape_deviation(const Eigen::Matrix2d& A, const Eigen::Matrix2d& B) {
  return global::similarity_error<double>(A, B) / B.squaredNorm();
}

/// Mean over the interior frames and over `triangles` of shape_deviation(A_i(t), B_i(t)).
double mean_deviation(const Animation& a, const Mesh& P, const global::Interpolation& interpolation,
                      const std::vector<Eigen::Index>& triangles) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t k = 1; k + 1 < a.t.size(); ++k)
    for (const Eigen::Index i : triangles) {
      sum += shape_deviation(interpolation.local_map(i, a.t[k]), global::triangle_linear_map(P, a.frames[k], i));
      ++count;
    }
  return sum / static_cast<double>(count);
}

/// One comparison of E^R with and without area weights on the graded bar: the mean shape deviation of the
/// large triangles (area ≥ ¼ of the largest) and of the small ones (area ≤ 4 × the smallest).
struct WeightingTrial {
  std::string setup;
  double large_unweighted, large_weighted, small_unweighted, small_weighted;
  Animation unweighted, weighted;
  std::size_t large_count, small_count;
  nlohmann::json to_json() const {
    return {{"setup", setup},
            {"large_triangles", large_count},
            {"small_triangles", small_count},
            {"large_unweighted", large_unweighted},
            {"large_weighted", large_weighted},
            {"small_unweighted", small_unweighted},
            {"small_weighted", small_weighted},
            {"unweighted", summary_of(unweighted)},
            {"weighted", summary_of(weighted)}};
  }
};

/// Both base vertices pinned, and loci through p_k, `pushed[k]`, q_k for the far corners given.
WeightingTrial weighting_trial(const shapes::MeshPairShapes& pair, int frames, const std::string& setup,
                               const std::vector<std::pair<Eigen::Index, Eigen::Vector2d>>& pushed) {
  const Mesh& P = pair.source;
  // Large: at least a quarter of the largest area; small: at most four times the smallest.
  double smallest_area = std::numeric_limits<double>::infinity(), largest_area = 0;
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i) {
    smallest_area = std::min(smallest_area, std::abs(P.doubled_signed_area(i)));
    largest_area = std::max(largest_area, std::abs(P.doubled_signed_area(i)));
  }
  std::vector<Eigen::Index> small, large;
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i) {
    if (std::abs(P.doubled_signed_area(i)) >= largest_area / 4) large.push_back(i);
    if (std::abs(P.doubled_signed_area(i)) <= 4 * smallest_area) small.push_back(i);
  }
  InterpolationOptions options = options_for(Energy::R, worm_base_pins(P));
  for (const auto& [k, middle] : pushed) {
    Eigen::Matrix2Xd points(2, 3);
    points << P.vertices.col(k), middle, pair.target.vertices.col(k);
    options.constraints.loci.push_back({k, points, constraint_weight});
  }
  const global::Interpolation plain(P, pair.target, options);
  // E_i ← Area_i E_i shrinks the local errors by the mean area; the constraint weights shrink alike so that
  // only the distribution over triangles changes, not the balance against the constraints.
  options.area_weighted = true;
  double mean_area = 0;
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i) mean_area += std::abs(P.doubled_signed_area(i)) / 2;
  mean_area /= static_cast<double>(P.triangle_count());
  for (auto& pin : options.constraints.pinned) pin.weight *= mean_area;
  for (auto& locus : options.constraints.loci) locus.weight *= mean_area;
  const global::Interpolation weighted(P, pair.target, options);
  WeightingTrial trial{setup,
                       0,
                       0,
                       0,
                       0,
                       animate("E^R unweighted", P, plain, frames),
                       animate("E^R area-weighted", P, weighted, frames),
                       large.size(),
                       small.size()};
  trial.large_unweighted = mean_deviation(trial.unweighted, P, plain, large);
  trial.large_weighted = mean_deviation(trial.weighted, P, weighted, large);
  trial.small_unweighted = mean_deviation(trial.unweighted, P, plain, small);
  trial.small_weighted = mean_deviation(trial.weighted, P, weighted, small);
  return trial;
}

Outcome check(const ClaimContext& ctx) {
  const shapes::MeshPairShapes pair = shapes::make_shape("graded-bend");
  const Mesh& P = pair.source;
  const int frames = ctx.pick(7, 21);
  const Eigen::Index upper = extreme_vertex(P, {1, 1e-3}), lower = extreme_vertex(P, {1, -1e-3});
  const Eigen::Vector2d middle_upper = (P.vertices.col(upper) + pair.target.vertices.col(upper)) / 2;
  const Eigen::Vector2d middle_lower = (P.vertices.col(lower) + pair.target.vertices.col(lower)) / 2;
  const Eigen::Vector2d base = P.vertices.col(extreme_vertex(P, {-1, -1e-3}));
  const Eigen::Vector2d half_gap = (middle_upper - middle_lower) / 2;
  const double length = (P.vertices.col(upper) - base).norm();
  const std::vector<WeightingTrial> trials = {
      weighting_trial(pair, frames,
                      "stretch: the far upper corner's path midpoint pushed 25% of the length away from the base",
                      {{upper, middle_upper + 0.25 * length * (middle_upper - base).normalized()}}),
      weighting_trial(pair, frames, "widen: the far corners' path midpoints pushed apart to twice their distance",
                      {{upper, middle_upper + half_gap}, {lower, middle_lower - half_gap}})};
  Outcome out;
  nlohmann::json per_trial = nlohmann::json::array();
  const WeightingTrial* failing = nullptr;
  for (const WeightingTrial& trial : trials) {
    per_trial.push_back(trial.to_json());
    if (!(trial.large_weighted < trial.large_unweighted) && !failing) failing = &trial;
  }
  out.verdict = failing ? Verdict::refuted : Verdict::confirmed;
  out.summary = "graded bar, mean E^R(A_i(t), B_i(t))/‖B_i‖² of the large triangles, area-weighted vs unweighted: ";
  for (const WeightingTrial& trial : trials)
    out.summary += trial.setup.substr(0, trial.setup.find(':')) + " " + std::to_string(trial.large_weighted) + " vs " +
                   std::to_string(trial.large_unweighted) + "; ";
  out.summary += failing ? "area weighting does not keep the large triangles more rigid in every setup"
                         : "area weighting keeps the large triangles more rigid";
  out.evidence.method =
      "E^R(A_i(t), B_i(t))/‖B_i(t)‖² averaged over interior frames, over the large (area ≥ ¼ max) and small (area ≤ 4 "
      "min) triangles";
  out.evidence.sample_size = static_cast<std::uint64_t>(2 * frames * static_cast<int>(trials.size()));
  out.evidence.details = {
      {"trials", per_trial},
      {"reading", "'more rigid' = closer to the local homotopy up to similarity, which is what E^R measures"},
      {"shape",
       "generated graded-bend (fine x < 1.5, coarse elsewhere; tapered, bent by π/2); both base "
       "vertices pinned; c = 1000, times the mean triangle area in the weighted runs"}};
  if (failing) out.counterexample = {{"shape", "graded-bend"}, {"trial", failing->to_json()}};
  if (ctx.draws_figures())
    out.figures = draw_animations(ctx, "kaji-fig6-fig7", P, {trials.back().unweighted, trials.back().weighted},
                                  {0, frames / 3, 2 * frames / 3, frames - 1}, "Kaji Figs 6/7: area weighting");
  return out;
}

}  // namespace
}  // namespace affinterp::claims::kaji_fig6_vs_fig7
