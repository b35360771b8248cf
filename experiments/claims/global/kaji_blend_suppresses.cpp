#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/animation.hpp"
#include "experiments/claims/global/figure_setups.hpp"

#include <Eigen/LU>
#include "theory/local/polar_decomposition.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::claims::kaji_blend_suppresses {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.blend.suppresses",
    .chapter = Chapter::global,
    .where = "Kaji §4",
    .statement = "In the blend w E^F + (1−w) E^R, a large w suppresses a triangle's rotation and scaling.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: "suppressed" = the rotation angle and log-scale of B_i(t) A_i(t)⁻¹ shrink as w grows.
// Method: the Fig 2 loci on the man; the blend w_i E^F + (1 − w_i) E^R with w_i = w ∈ {0, ½, 0.9, 1} on the head's
//   triangles (centroid in the top tenth of the height) and 0 elsewhere; mean |rotation| and |log scale| of the
//   head over interior frames must be non-increasing in w and smaller at w = 1 than at w = 0.
// Sizes: quick 7 frames; full 21.

using global::Energy;
using global::InterpolationOptions;
using global::Mesh;
using namespace global_figures;

/// The rotation angle and log-scale of B relative to A: B A⁻¹ = R_φ S', returns (|φ|, |log √det(BA⁻¹)|).
std::pair<double, double> relative_rotation_and_scale(const Eigen::Matrix2d& A, const Eigen::Matrix2d& B) {
  const Eigen::Matrix2d relative = B * A.inverse();
  if (relative.determinant() <= 0) return {std::numbers::pi, std::numeric_limits<double>::infinity()};
  return {std::abs(affinterp::local::polar_decomposition<double>(relative).theta),
          std::abs(std::log(relative.determinant()) / 2)};
}

Outcome check(const ClaimContext& ctx) {
  const LociSetup setup = swung_loci();
  const Mesh& P = setup.pair.source;
  const int frames = ctx.pick(7, 21);
  // The head: triangles whose centroid lies in the top tenth of the figure's height.
  const double top = P.vertices.row(1).maxCoeff(), bottom = P.vertices.row(1).minCoeff();
  std::vector<Eigen::Index> head;
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i)
    if ((P.corner(i, 0).y() + P.corner(i, 1).y() + P.corner(i, 2).y()) / 3 > top - 0.1 * (top - bottom))
      head.push_back(i);
  nlohmann::json per_w = nlohmann::json::array();
  std::vector<std::pair<double, double>> measured;
  std::vector<Animation> animations;
  for (const double w : {0.0, 0.5, 0.9, 1.0}) {
    InterpolationOptions options = options_for(Energy::blend, setup.constraints);
    options.blend_weights = Eigen::VectorXd::Zero(P.triangle_count());
    for (const Eigen::Index i : head) options.blend_weights[i] = w;
    if (w == 0) options.energy = Energy::R;  // the blend with every w_i = 0 is E^R
    const global::Interpolation interpolation(P, setup.pair.target, options);
    const Animation a = animate("w = " + std::to_string(w).substr(0, 3) + " on the head", P, interpolation, frames);
    double rotation = 0, scale = 0;
    std::size_t count = 0;
    for (std::size_t k = 1; k + 1 < a.t.size(); ++k)
      for (const Eigen::Index i : head) {
        const auto [phi, s] = relative_rotation_and_scale(interpolation.local_map(i, a.t[k]),
                                                          global::triangle_linear_map(P, a.frames[k], i));
        rotation += phi, scale += s, ++count;
      }
    measured.emplace_back(rotation / static_cast<double>(count), scale / static_cast<double>(count));
    per_w.push_back(
        {{"w", w}, {"mean_abs_rotation_rad", measured.back().first}, {"mean_abs_log_scale", measured.back().second}});
    animations.push_back(a);
  }
  bool monotone = true;
  for (std::size_t k = 1; k < measured.size(); ++k)
    monotone = monotone && measured[k].first <= measured[k - 1].first + 1e-12 &&
               measured[k].second <= measured[k - 1].second + 1e-12;
  Outcome out;
  out.verdict = monotone && measured.back().first < measured.front().first ? Verdict::confirmed : Verdict::refuted;
  out.summary = "head triangles' rotation/scale relative to A_i(t): w = 0 → " + std::to_string(measured.front().first) +
                " rad, " + std::to_string(measured.front().second) + "; w = 1 → " +
                std::to_string(measured.back().first) + " rad, " + std::to_string(measured.back().second) +
                (monotone ? " (non-increasing in w)" : " (not monotone in w)");
  out.evidence.method = "blend w_i E^F + (1 − w_i) E^R with w_i = w on the head triangles, 0 elsewhere; the Fig 2 loci";
  out.evidence.sample_size = static_cast<std::uint64_t>(4 * frames);
  out.evidence.details = {
      {"per_w", per_w},
      {"head_triangles", head.size()},
      {"reading", "suppressed = the rotation angle and log-scale of B_i(t) A_i(t)⁻¹ shrink as w grows"}};
  if (out.verdict == Verdict::refuted) out.counterexample = {{"shape", "man-wave"}, {"per_w", per_w}};
  if (ctx.draws_figures())
    out.figures = draw_animations(ctx, "kaji-blend", P, {animations.front(), animations.back()},
                                  {0, frames / 3, 2 * frames / 3, frames - 1}, "Blend on the head");
  return out;
}

}  // namespace
}  // namespace affinterp::claims::kaji_blend_suppresses
