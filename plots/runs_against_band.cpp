#include "plots/runs_against_band.hpp"

#include "plots/gnuplot_process.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace affinterp::plots {

namespace {

/// A band edge in gnuplot coordinates: an infinite edge is the panel's edge.
std::string edge(double value, const char* graph_edge) {
  if (!std::isfinite(value)) return std::string("graph ") + graph_edge;
  std::ostringstream out;
  out.precision(17);
  out << "first " << value;
  return out.str();
}

}  // namespace

std::vector<std::string> draw_runs_against_band(const std::filesystem::path& stem, const std::string& title,
                                                const std::vector<BandPanel>& panels) {
  Figure figure(stem);
  std::size_t most_runs = 1;
  std::ostringstream script;
  script << "set multiplot layout 1," << panels.size() << " title " << gnuplot_string(title) << "\n"
         << "set style fill transparent solid 0.25 noborder\nset bars 2\nset offsets 0.5, 0.5, 0, 0\n"
            "set xtics rotate by -25 left noenhanced\nset bmargin 6\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const BandPanel& panel = panels[p];
    most_runs = std::max(most_runs, panel.runs.size());
    Table points;  // x, value, lo, hi
    std::ostringstream tics;
    double low = panel.band_lo, high = panel.band_hi;
    for (std::size_t r = 0; r < panel.runs.size(); ++r) {
      const RunValue& run = panel.runs[r];
      const auto [lo, hi] = run.interval.value_or(std::pair{run.value, run.value});
      points.push_back({static_cast<double>(r), run.value, lo, hi});
      tics << (r ? ", " : "") << gnuplot_string(run.label) << " " << r;
      low = std::isfinite(low) ? std::min(low, lo) : lo;
      high = std::isfinite(high) ? std::max(high, hi) : hi;
    }
    if (std::isfinite(panel.band_lo)) high = std::max(high, panel.band_lo);  // the band's finite edges in view
    if (std::isfinite(panel.band_hi)) low = std::min(low, panel.band_hi);
    std::string name = "p";
    name += std::to_string(p);
    figure.data(name, points);
    const double margin = 0.15 * std::max(high - low, 1e-9);
    script << "unset object\nset object 1 rect from graph 0, " << edge(panel.band_lo, "0") << " to graph 1, "
           << edge(panel.band_hi, "1") << " behind fc rgb '#009e73' fs transparent solid 0.25 noborder\n"
           << "set title " << gnuplot_string(panel.title) << " noenhanced\nset ylabel " << gnuplot_string(panel.unit)
           << "\nset yrange [" << low - margin << ":" << high + margin
           << "]\nset xrange [-0.5:" << (panel.runs.empty() ? 0.5 : static_cast<double>(panel.runs.size()) - 0.5)
           << "]\nset xtics (" << tics.str() << ")\n"
           << "plot $" << name << " using 1:2:3:4 with yerrorbars lt 1 pt 7 ps 1.2\n";
  }
  script << "unset multiplot\n";
  figure.size(std::max<int>(520, static_cast<int>(panels.size() * (260 + 90 * most_runs))), 520).script(script.str());
  return figure.render();
}

}  // namespace affinterp::plots
