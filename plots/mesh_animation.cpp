#include "plots/mesh_animation.hpp"

#include "plots/gnuplot_process.hpp"
#include "plots/mesh_tables.hpp"

#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace affinterp::plots {

namespace fs = std::filesystem;

std::optional<fs::path> find_convert() { return find_program("convert"); }

bool write_animation_gif(const fs::path& gif, const Eigen::Matrix3Xi& triangles, const std::vector<MeshFrame>& frames,
                         int delay_cs) {
  const auto convert = find_convert();
  if (!convert || frames.empty()) return false;
  Eigen::Vector2d lo = frames.front().vertices.rowwise().minCoeff(), hi = frames.front().vertices.rowwise().maxCoeff();
  for (const MeshFrame& frame : frames) {
    lo = lo.cwiseMin(frame.vertices.rowwise().minCoeff());
    hi = hi.cwiseMax(frame.vertices.rowwise().maxCoeff());
  }
  const Eigen::Vector2d margin = 0.05 * (hi - lo).cwiseMax(1e-9);
  lo -= margin;
  hi += margin;
  const int width = 480, height = std::clamp(static_cast<int>(width * (hi.y() - lo.y()) / (hi.x() - lo.x())), 120, 960);

  fs::path folder = gif.parent_path().empty() ? fs::path(".") : gif.parent_path();
  folder /= "animation-" + std::to_string(getpid());
  fs::create_directories(folder);
  const fs::path log = folder / "gnuplot.log";
  {
    const auto gp = start_gnuplot(log);
    *gp << std::setprecision(12) << "unset border\nunset tics\nunset grid\nset size ratio -1\n"
       << "set margins 0,0,0,0\nset xrange [" << lo.x() << ":" << hi.x() << "]\nset yrange [" << lo.y() << ":" << hi.y()
       << "]\nset terminal pngcairo size " << width << "," << height << " font 'DejaVu Sans,10'\n";
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const MeshTables tables = mesh_tables(triangles, frames[f].vertices);
      write_datablock(*gp, "edges", tables.edges);
      write_datablock(*gp, "triangles", tables.triangles);
      write_datablock(*gp, "flipped", tables.flipped);
      std::ostringstream name;
      name << "frame_" << std::setw(4) << std::setfill('0') << f << ".png";
      *gp << "set output " << gnuplot_string((folder / name.str()).string()) << "\nset label 1 " << gnuplot_string(frames[f].label)
         << " at graph 0.02, graph 0.95 noenhanced\n"
         << mesh_plot_command(!tables.triangles.empty(), !tables.flipped.empty()) << "unset output\n";
    }
  }
  const std::string command = shell_quoted(*convert) + " -delay " + std::to_string(delay_cs) + " -loop 0 " +
                              shell_quoted(folder) + "/frame_*.png " + shell_quoted(gif) + " 2>/dev/null";
  const int status = std::system(command.c_str());
  std::error_code ignored;
  const bool drawn = fs::exists(folder / "frame_0000.png");
  fs::remove_all(folder, ignored);
  if (!drawn) throw std::runtime_error("gnuplot drew no animation frames");
  if (status != 0 || !fs::exists(gif)) throw std::runtime_error("convert failed to write " + gif.string());
  return true;
}

}  // namespace affinterp::plots
