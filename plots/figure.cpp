#include "plots/figure.hpp"

#include "plots/gnuplot_process.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace affinterp::plots {

namespace fs = std::filesystem;

Figure& Figure::size(int width_px, int height_px) {
  width_ = width_px;
  height_ = height_px;
  return *this;
}

Figure& Figure::data(const std::string& name, const Table& table) {
  tables_.emplace_back(name, table);
  return *this;
}

Figure& Figure::script(const std::string& commands) {
  script_ += commands;
  if (!script_.empty() && script_.back() != '\n') script_ += '\n';
  return *this;
}

const std::string& house_style() {
  static const std::string style =
      "set encoding utf8\n"
      "set grid lc rgb '#dddddd'\n"
      "set border lc rgb '#555555'\n"
      "set key noautotitle\n"
      "set linetype 1 lc rgb '#0072b2' lw 2\n"
      "set linetype 2 lc rgb '#d55e00' lw 2\n"
      "set linetype 3 lc rgb '#009e73' lw 2\n"
      "set linetype 4 lc rgb '#cc79a7' lw 2\n"
      "set linetype 5 lc rgb '#e69f00' lw 2\n"
      "set linetype 6 lc rgb '#56b4e9' lw 2\n"
      "set linetype 7 lc rgb '#000000' lw 2\n";
  return style;
}

std::vector<std::string> Figure::render() const {
  std::ostringstream blocks;
  for (const auto& [name, table] : tables_) write_datablock(blocks, name, table);

  const fs::path log = fs::path(stem_.string() + ".gnuplot.log");
  const std::vector<std::pair<std::string, std::string>> formats = {
      {"png", "pngcairo enhanced font 'DejaVu Sans,11'"},
      {"svg", "svg enhanced font 'DejaVu Sans,11' background '#ffffff'"},
  };
  std::vector<std::string> written;
  for (const auto& [extension, terminal] : formats) {
    const fs::path out = fs::path(stem_.string() + "." + extension);
    fs::remove(out);
    {
      const auto gp = start_gnuplot(log);
      *gp << blocks.str();
      *gp << "set terminal " << terminal << " size " << width_ << "," << height_ << "\n";
      *gp << "set output " << gnuplot_string(out.string()) << "\n" << script_ << "unset output\n";
    }  // gnuplot has exited and the file is complete
    const std::string error = first_error_line(log);
    if (!error.empty() || !fs::exists(out) || fs::file_size(out) == 0)
      throw std::runtime_error("gnuplot failed on " + out.string() + ": " +
                               (error.empty() ? "no output written" : error));
    written.push_back(out.filename().string());
  }
  fs::remove(log);
  return written;
}

}  // namespace affinterp::plots
