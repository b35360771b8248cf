#pragma once
// The figure of an "iff" theorem's sweep: a region map (plots/region_map.hpp) of where the printed condition
// and the independently decided property hold.
#include "experiments/claims/context.hpp"
#include "plots/region_map.hpp"

#include <string>
#include <vector>

namespace affinterp::claims::local {

/// Draws `points` to <figure_dir>/<name>.png and .svg, each cell reaching `half_cell` either side of its
/// point; returns the references for Outcome::figures.
inline std::vector<std::string> draw_region_figure(const RunSettings& ctx, const std::string& name,
                                                   const std::string& title, const std::string& x_label,
                                                   const std::string& y_label,
                                                   const std::vector<plots::RegionPoint>& points, double half_cell) {
  plots::draw_region_map(ctx.figure_stem(name), title, x_label, y_label, points, half_cell, half_cell);
  return {RunSettings::figure_ref(name + ".png"), RunSettings::figure_ref(name + ".svg")};
}

}  // namespace affinterp::claims::local
