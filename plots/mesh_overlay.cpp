#include "plots/mesh_overlay.hpp"

#include "plots/gnuplot_process.hpp"
#include "plots/mesh_tables.hpp"

#include <sstream>
#include <stdexcept>

namespace affinterp::plots {

std::vector<std::string> draw_overlay(const std::filesystem::path& stem, const Eigen::Matrix3Xi& triangles,
                                      const std::vector<MeshFrame>& frames, const std::vector<Curve>& curves,
                                      const std::string& title) {
  if (frames.empty()) throw std::invalid_argument("draw_overlay: no frames");
  Table edges, flipped;  // edges carry a third column, the frame's place in time (0 first … 1 last)
  Eigen::Vector2d lo = frames.front().vertices.rowwise().minCoeff(), hi = frames.front().vertices.rowwise().maxCoeff();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const MeshTables tables = mesh_tables(triangles, frames[f].vertices);
    const double shade = frames.size() > 1 ? static_cast<double>(f) / static_cast<double>(frames.size() - 1) : 1.0;
    for (Row row : tables.edges) {
      if (!row.empty()) row.push_back(shade);
      edges.push_back(row);
    }
    append(flipped, tables.flipped);
    lo = lo.cwiseMin(frames[f].vertices.rowwise().minCoeff()),
    hi = hi.cwiseMax(frames[f].vertices.rowwise().maxCoeff());
  }
  Figure figure(stem);
  std::ostringstream plot;
  plot << "plot $edges using 1:2:3 with lines lc palette lw 0.6 notitle";
  if (!flipped.empty()) {
    figure.data("flipped", flipped);
    plot << ", $flipped with filledcurves closed fc rgb '#e03030' fs solid noborder title 'flipped'";
  }
  for (std::size_t c = 0; c < curves.size(); ++c) {
    Table table;
    for (Eigen::Index k = 0; k < curves[c].points.cols(); ++k)
      table.push_back({curves[c].points(0, k), curves[c].points(1, k)});
    const std::string name = "curve" + std::to_string(c);
    figure.data(name, table);
    plot << ", $" << name << " " << curves[c].style << " "
         << (curves[c].label.empty() ? "notitle" : "title " + gnuplot_string(curves[c].label));
    lo = lo.cwiseMin(curves[c].points.rowwise().minCoeff()), hi = hi.cwiseMax(curves[c].points.rowwise().maxCoeff());
  }
  const Eigen::Vector2d margin = 0.05 * (hi - lo).cwiseMax(1e-9) + Eigen::Vector2d::Constant(1e-9);
  std::ostringstream script;
  script.precision(17);
  script << "unset border\nunset tics\nunset grid\nunset colorbox\nset size ratio -1\n"
         << "set palette defined (0 '#c4d7ea', 1 '#1f3f66')\nset cbrange [0:1]\n"
         << "set key outside right top noenhanced\n";
  if (!title.empty()) script << "set title " << gnuplot_string(title) << " noenhanced\n";
  script << "set xrange [" << lo.x() - margin.x() << ":" << hi.x() + margin.x() << "]\nset yrange ["
         << lo.y() - margin.y() << ":" << hi.y() + margin.y() << "]\n"
         << plot.str() << "\n";
  return figure.size(900, 700).data("edges", edges).script(script.str()).render();
}

}  // namespace affinterp::plots
