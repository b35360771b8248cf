#include "plots/engine_scale_curve.hpp"

#include "plots/gnuplot_process.hpp"

namespace affinterp::plots {

std::vector<std::string> draw_engine_scale(const std::filesystem::path& stem, const std::vector<CostSeries>& series,
                                           const std::vector<CostTarget>& targets) {
  Figure figure(stem);
  std::string plot = "plot ";
  for (std::size_t c = 0; c < series.size(); ++c) {
    figure.data("c" + std::to_string(c), series[c].points);
    plot += std::string(c ? ", " : "") + "$c" + std::to_string(c) + " using 1:2 axes x1y" +
            (series[c].memory ? "2" : "1") + " with linespoints lt " + std::to_string(series[c].colour) + " dt " +
            std::to_string(series[c].dash) + " title " + gnuplot_string(series[c].title);
  }
  std::string lines;
  for (const CostTarget& target : targets) {
    const std::string axis = target.memory ? "second " : "first ", value = std::to_string(target.value);
    lines += "set arrow from graph 0, " + axis + value + " to graph 1, " + axis + value +
             " nohead dt 3 lc rgb '#888888'\nset label " + gnuplot_string(target.label) + " at graph " +
             (target.memory ? "0.02" : "0.72") + ", " + axis + value + " offset 0,0.6 tc rgb '#666666'\n";
  }
  figure.size(1100, 700).script(
      "set logscale xy\nset logscale y2\nset xlabel 'triangles'\nset ylabel 'time (ms)'\n"
      "set y2label 'peak memory (MB)'\nset ytics nomirror\nset y2tics\nset xrange [500:2e6]\n"
      "set key outside below center horizontal maxrows 4 font ',9'\n"
      // (a plain ~ is gnuplot's overprint in enhanced text)
      "set title 'global engine: cost against mesh size (bench\\_scale; exponent p per curve, cost ∝ n^p, fitted "
      "from 65k)'\n" +
      lines + plot + "\n");
  return figure.render();
}

}  // namespace affinterp::plots
