#pragma once
// The global engine's cost against mesh size (bench_scale): time against triangles, log-log, one line per
// measured quantity (colour: the quantity, dash: the back-end), memory on the right axis, with the targets as
// horizontal lines.
#include "plots/figure.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

/// One measured quantity: (triangles, value) points in ascending size.
struct CostSeries {
  std::string title;
  Table points;
  int colour = 1;       ///< the house style's line colour
  int dash = 1;         ///< gnuplot's dash type
  bool memory = false;  ///< MB on the right axis, else ms on the left
};

/// A target drawn as a dashed horizontal line, labelled.
struct CostTarget {
  double value;
  std::string label;
  bool memory = false;  ///< MB on the right axis, else ms on the left
};

/// Draws `series` and `targets` to stem.png and stem.svg; returns the file names.
std::vector<std::string> draw_engine_scale(const std::filesystem::path& stem, const std::vector<CostSeries>& series,
                                           const std::vector<CostTarget>& targets);

}  // namespace affinterp::plots
