#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/animation.hpp"
#include "experiments/claims/global/figure_setups.hpp"

#include <Eigen/LU>

#include <limits>
#include <string>

namespace affinterp::claims::kaji_global_flips {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.global.flips",
    .chapter = Chapter::global,
    .where = "Kaji §5",
    .statement = "Unlike the local exp-log homotopy, the global interpolation can flip triangles.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: "can flip" asks for one configuration where the global interpolation flips a triangle while every local
//   A^E_i(t) keeps det > 0 (Kaji §3).
// Method: E^R, then E^F, interpolations (exp homotopy) of the man with the Fig 2 loci; the first that flips decides,
//   with the local determinants checked at every frame. None found would be inconclusive, not refuted.
// Sizes: quick 11 frames; full 41.

using global::Energy;
using global::Mesh;
using namespace global_figures;

Outcome check(const ClaimContext& ctx) {
  const LociSetup setup = swung_loci();
  const Mesh& P = setup.pair.source;
  const int frames = ctx.pick(11, 41);
  Outcome out;
  nlohmann::json tried = nlohmann::json::array();
  for (const Energy energy : {Energy::R, Energy::F}) {
    const global::Interpolation interpolation(P, setup.pair.target, options_for(energy, setup.constraints));
    const Animation a = animate("E^" + global::to_string(energy), P, interpolation, frames);
    double local_min_det = std::numeric_limits<double>::infinity();  // det A^E_i(t) > 0 (Kaji §3)
    for (const double t : a.t)
      for (Eigen::Index i = 0; i < P.triangle_count(); ++i)
        local_min_det = std::min(local_min_det, interpolation.local_map(i, t).determinant());
    tried.push_back({{"energy", "E^" + global::to_string(energy)},
                     {"most_flipped", a.most_flips()},
                     {"min_det_B", a.min_det()},
                     {"min_det_local_A_E", local_min_det}});
    if (a.most_flips() > 0 && local_min_det > 0 && out.verdict == Verdict::pending) {
      std::size_t k = 0;
      while (a.metrics[k].flipped_triangles == 0) ++k;
      out.verdict = Verdict::confirmed;
      out.summary = "E^" + global::to_string(energy) + " with the Fig 2 loci flips " +
                    std::to_string(a.metrics[k].flipped_triangles) + " triangles at t = " + std::to_string(a.t[k]) +
                    " while every local A^E_i(t) has det > 0";
      if (ctx.draws_figures())
        out.figures = draw_animations(ctx, "kaji-global-flips", P, {a}, {0, static_cast<int>(k), frames - 1},
                                      "Global interpolation flips");
    }
  }
  if (out.verdict == Verdict::pending) {
    out.verdict = Verdict::inconclusive;
    out.summary = "no flip found in the configurations tried; a wider search would decide";
  }
  out.evidence.method = "flip counts of E^R and E^F interpolations (exp homotopy) of the man with the Fig 2 loci";
  out.evidence.sample_size = static_cast<std::uint64_t>(2 * frames);
  out.evidence.details = {{"tried", tried}};
  return out;
}

}  // namespace
}  // namespace affinterp::claims::kaji_global_flips
