#pragma once
// A figure: named data tables and a gnuplot script, rendered to PNG and SVG through gnuplot-iostream.
// Data are written with 17 significant digits as gnuplot datablocks ($name), so the script can plot
// the same data several times (multiplot panels, both output formats).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::plots {

using Row = std::vector<double>;
/// Rows of numbers; an empty row writes a blank line (gnuplot: a break between polylines; two in a
/// row start a new data set addressed by `index`).
using Table = std::vector<Row>;

class Figure {
 public:
  /// Draws to `stem`.png and `stem`.svg.
  explicit Figure(std::filesystem::path stem) : stem_(std::move(stem)) {}

  Figure& size(int width_px, int height_px);
  /// Makes `table` available to the script as $name.
  Figure& data(const std::string& name, const Table& table);
  /// Appends gnuplot commands (everything after the terminal is set).
  Figure& script(const std::string& commands);

  /// Runs gnuplot once per format; returns the file names written ("stem.png", "stem.svg").
  /// Throws std::runtime_error with gnuplot's first error line when a file is not produced.
  std::vector<std::string> render() const;

 private:
  std::filesystem::path stem_;
  int width_ = 900, height_ = 600;
  std::vector<std::pair<std::string, Table>> tables_;
  std::string script_;
};

/// The house style: fonts, grid, line colours. Prepended to every figure's script.
const std::string& house_style();

}  // namespace affinterp::plots
