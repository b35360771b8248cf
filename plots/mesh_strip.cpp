#include "plots/mesh_strip.hpp"

#include "plots/gnuplot_process.hpp"
#include "plots/mesh_tables.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace affinterp::plots {

std::string mesh_plot_command(bool has_triangles, bool has_flipped) {
  std::string command = "plot ";
  if (has_triangles) command += "$triangles with filledcurves closed fc rgb '#d6e6f5' fs solid noborder, ";
  if (has_flipped) command += "$flipped with filledcurves closed fc rgb '#e03030' fs solid noborder, ";
  return command + "$edges with lines lc rgb '#2c5d8a' lw 0.6\n";
}

std::vector<std::string> draw_filmstrip(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                        const std::vector<MeshFrame>& frames, const std::string& title) {
  if (frames.empty()) throw std::invalid_argument("draw_filmstrip: no frames");
  double width = 0, height = 0;
  for (const MeshFrame& frame : frames) {
    const Eigen::Vector2d extent = frame.vertices.rowwise().maxCoeff() - frame.vertices.rowwise().minCoeff();
    width = std::max(width, extent.x());
    height = std::max(height, extent.y());
  }
  const double cell = std::max(width, 1e-9) * 1.15;  // each frame centred in a cell of equal width
  MeshTables all;
  std::ostringstream labels;
  labels.precision(17);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Eigen::Vector2d lo = frames[f].vertices.rowwise().minCoeff(), hi = frames[f].vertices.rowwise().maxCoeff();
    const double centre_x = cell * (static_cast<double>(f) + 0.5);
    const Eigen::Vector2d offset(centre_x - (lo.x() + hi.x()) / 2, -(lo.y() + hi.y()) / 2);
    const MeshTables tables = mesh_tables(triangles, frames[f].vertices, offset);
    append(all.edges, tables.edges);
    append(all.triangles, tables.triangles);
    append(all.flipped, tables.flipped);
    labels << "set label " << f + 1 << " " << gnuplot_string(frames[f].label) << " at " << centre_x << "," << -0.5 * height - 0.06 * cell
           << " center font ',10' noenhanced\n";
  }
  const double total_width = cell * static_cast<double>(frames.size());
  const double total_height = std::max(height, 1e-9) + 0.25 * cell;
  const int pixel_width = std::clamp(static_cast<int>(220 * frames.size()), 400, 2400);
  const int pixel_height = std::clamp(static_cast<int>(pixel_width * total_height / total_width) + (title.empty() ? 20 : 50), 150, 1400);

  std::ostringstream script;
  script.precision(17);
  script << "unset border\nunset tics\nunset grid\nset size ratio -1\nset margins 1,1,1," << (title.empty() ? 1 : 3) << "\n";
  if (!title.empty()) script << "set title " << gnuplot_string(title) << " noenhanced\n";
  script << "set xrange [0:" << total_width << "]\nset yrange [" << -0.5 * height - 0.15 * cell << ":" << 0.5 * height + 0.05 * cell
         << "]\n" << labels.str() << mesh_plot_command(!all.triangles.empty(), !all.flipped.empty());
  Figure figure(stem);
  figure.size(pixel_width, pixel_height).data("edges", all.edges);
  if (!all.triangles.empty()) figure.data("triangles", all.triangles);
  if (!all.flipped.empty()) figure.data("flipped", all.flipped);
  return figure.script(script.str()).render();
}

}  // namespace affinterp::plots
