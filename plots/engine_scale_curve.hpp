#pragma once
// The global engine's cost against mesh size (bench_scale): time against triangles, log-log, one line per
// measured quantity, with the targets as horizontal lines.
#include "plots/figure.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

/// One measured quantity: (triangles, ms) points in ascending size.
struct CostSeries {
  std::string title;
  Table points;
};

/// A target drawn as a dashed horizontal line, labelled.
struct CostTarget {
  double ms;
  std::string label;
};

/// Draws `series` and `targets` to stem.png and stem.svg; returns the file names.
std::vector<std::string> draw_engine_scale(const std::filesystem::path& stem, const std::vector<CostSeries>& series,
                                           const std::vector<CostTarget>& targets);

}  // namespace affinterp::plots
