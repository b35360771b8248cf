#include "plots/engine_scale_curve.hpp"

#include "plots/gnuplot_process.hpp"

namespace affinterp::plots {

std::vector<std::string> draw_engine_scale(const std::filesystem::path& stem, const std::vector<CostSeries>& series,
                                           const std::vector<CostTarget>& targets) {
  Figure figure(stem);
  std::string plot = "plot ";
  for (std::size_t c = 0; c < series.size(); ++c) {
    figure.data("c" + std::to_string(c), series[c].points);
    plot += std::string(c ? ", " : "") + "$c" + std::to_string(c) + " using 1:2 with linespoints title " +
            gnuplot_string(series[c].title);
  }
  std::string lines;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const std::string ms = std::to_string(targets[t].ms);
    lines += "set arrow from graph 0, first " + ms + " to graph 1, first " + ms + " nohead dt " +
             std::to_string(t + 2) + " lc rgb '#888888'\nset label " + gnuplot_string(targets[t].label) +
             " at graph 0.7, first " + ms + " offset 0,0.6 tc rgb '#666666'\n";
  }
  figure.size(900, 560).script(
      "set logscale xy\nset xlabel 'triangles'\nset ylabel 'time (ms)'\nset key top left\n"
      "set title 'global engine: cost against mesh size (bench\\_scale)'\n" +
      lines + plot + "\n");
  return figure.render();
}

}  // namespace affinterp::plots
