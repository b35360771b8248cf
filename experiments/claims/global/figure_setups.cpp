#include "experiments/claims/global/figure_setups.hpp"

#include <utility>

namespace affinterp::claims::global_figures {

global::InterpolationOptions options_for(global::Energy energy, global::Constraints constraints) {
  global::InterpolationOptions options;
  options.energy = energy;
  options.area_weighted = false;  // the plain sum of Kaji §4, as in Figs. 2–6
  options.constraints = std::move(constraints);
  return options;
}

LociSetup swung_loci() {
  LociSetup setup{shapes::make_shape("man-wave"), {}};
  const global::Mesh& P = setup.pair.source;
  const Eigen::Vector2d centre = (P.vertices.rowwise().mean() + setup.pair.target.vertices.rowwise().mean()) / 2;
  const Eigen::Matrix2d quarter = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  for (const Eigen::Index k : {extreme_vertex(P, {0, 1}), extreme_vertex(P, {0, -1})}) {
    const Eigen::Vector2d p = P.vertices.col(k), q = setup.pair.target.vertices.col(k);
    Eigen::Matrix2Xd points(2, 3);
    points << p, centre + quarter * ((p + q) / 2 - centre), q;
    setup.constraints.loci.push_back({k, points, constraint_weight});
  }
  return setup;
}

global::Constraints worm_base_pins(const global::Mesh& P) {
  return {{{extreme_vertex(P, {-1, -1e-3}), constraint_weight}, {extreme_vertex(P, {-1, 1e-3}), constraint_weight}},
          {},
          {},
          {}};
}

bool fails(const Animation& a) { return a.most_flips() > 0 || a.min_det() < extreme_shrink; }

nlohmann::json summary_of(const Animation& a) {
  return {{"most_flipped_triangles_in_a_frame", a.most_flips()}, {"min_det_over_frames", a.min_det()}};
}

}  // namespace affinterp::claims::global_figures
