#pragma once
// A measured figure across recorded runs: each run's value with its 95% interval as an error bar,
// over the shaded band of values a claim or target allows, one panel per figure, so that a reader sees whether
// the runs agree and which machine differs.
#include "plots/figure.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::plots {

/// One run's figure: its label on the axis (its date and machine, e.g. "<date> Xeon"), value and interval (none: a
/// point only).
struct RunValue {
  std::string label;
  double value = 0;
  std::optional<std::pair<double, double>> interval;
};

/// One panel: a figure across the runs, against [band_lo, band_hi] (an infinite edge runs off the panel).
struct BandPanel {
  std::string title;
  std::string unit;
  double band_lo = 0, band_hi = 0;
  std::vector<RunValue> runs;
};

/// Draws the panels side by side to stem.png and stem.svg under `title`; returns the file names.
std::vector<std::string> draw_runs_against_band(const std::filesystem::path& stem, const std::string& title,
                                                const std::vector<BandPanel>& panels);

}  // namespace affinterp::plots
