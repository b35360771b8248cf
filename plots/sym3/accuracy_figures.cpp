#include "plots/sym3/accuracy_figures.hpp"

#include "plots/figure.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace affinterp::plots {

namespace {

/// The names separated by spaces, for gnuplot's word(names, i).
std::string words(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += (joined.empty() ? "" : " ") + name;
  return joined;
}

}  // namespace

std::vector<std::string> draw_error_vs_gap(const std::filesystem::path& stem,
                                           const std::vector<std::string>& algorithms,
                                           const std::vector<GapErrors>& errors) {
  constexpr double floor = 1e-18, ceiling = 1e16;
  const auto point = [&](const std::pair<double, double>& p) -> Row {
    return {p.first > 0 ? p.first : floor, std::isfinite(p.second) ? std::max(p.second, floor) : ceiling};
  };
  Table pairs, triples;
  for (const GapErrors& e : errors) {
    for (const auto& p : e.pairs) pairs.push_back(point(p));
    for (const auto& p : e.triples) triples.push_back(point(p));
    pairs.push_back({}), pairs.push_back({});
    triples.push_back({}), triples.push_back({});
  }
  const std::string panel =
      "set logscale xy\n"
      "set format x '10^{%L}'\nset format y '10^{%L}'\n"
      "set xrange [5e-19:1]\nset yrange [5e-19:1e17]\n"
      "set xlabel 'eigenvalue gap (0 drawn at 10^{-18})'\n"
      "set ylabel 'max certified relative Frobenius error (NaN drawn at 10^{16})'\n"
      "set key outside right top\n"
      "set linetype 8 lc rgb '#999999' lw 2 dt 2\n"
      "set linetype 9 lc rgb '#6a3d9a' lw 2 dt 3\n"
      "set linetype 10 lc rgb '#b15928' lw 2 dt 4\n"
      "set arrow from 1e-6, graph 0 to 1e-6, graph 1 nohead dt 2 lc rgb '#888888'\n"
      "set arrow from graph 0, first 1e-6 to graph 1, first 1e-6 nohead dt 2 lc rgb '#888888'\n";
  const auto plot = [&](const std::string& block) {
    return "plot for [i=0:" + std::to_string(algorithms.size() - 1) + "] $" + block +
           " index i using 1:2 with linespoints lt (i%10)+1 pt (i%10)+1 ps 0.8 title word(names, i+1)\n";
  };
  return Figure(stem)
      .size(1100, 900)
      .data("pairs", pairs)
      .data("triples", triples)
      .script("names = '" + words(algorithms) + "'\n" + panel +
              "set multiplot layout 2,1\n"
              "set title 'pairs λ, λ + gap (third eigenvalue free), in [0, 3]'\n" +
              plot("pairs") + "set title 'triples λ, λ + gap, λ + 2 gap, in [0, 3]'\n" + plot("triples") +
              "unset multiplot\n")
      .render();
}

std::vector<std::string> draw_peer_errors(const std::filesystem::path& stem, const std::vector<std::string>& families,
                                          const std::vector<std::string>& algorithms,
                                          const std::vector<std::vector<std::optional<double>>>& worst) {
  // log₁₀ of the error drawn: an exact result at −18, errors of 10 and more at 1, a failure at 2 (black).
  constexpr double floor = -18, ceiling = 1, failed = 2;
  Table cells;
  for (std::size_t f = 0; f < families.size(); ++f) {
    for (std::size_t a = 0; a < algorithms.size(); ++a) {
      const std::optional<double>& w = worst[f][a];
      cells.push_back({static_cast<double>(a), static_cast<double>(f),
                       w ? std::clamp(std::log10(std::max(*w, 1e-300)), floor, ceiling) : failed});
    }
    cells.push_back({});
  }
  std::ostringstream ytics, xtics;
  for (std::size_t f = 0; f < families.size(); ++f) ytics << (f ? ", " : "") << '"' << families[f] << "\" " << f;
  for (std::size_t a = 0; a < algorithms.size(); ++a) xtics << (a ? ", " : "") << '"' << algorithms[a] << "\" " << a;
  return Figure(stem)
      .size(1200, 1500)
      .data("cells", cells)
      .script(
          "set title 'worst certified relative error of exp S per family (Arb references); black: "
          "NaN/∞ where exp S is finite, or finite where it overflows'\n"
          "set xtics (" +
          xtics.str() +
          ") rotate by -40 left font ',9'\n"
          "set ytics (" +
          ytics.str() +
          ") font ',8'\n"
          "set xrange [-0.5:" +
          std::to_string(algorithms.size() - 0.5) +
          "]\n"
          "set yrange [" +
          std::to_string(families.size() - 0.5) +
          ":-0.5]\n"
          "set cbrange [-18:2]\nset cblabel 'log_{10} worst error'\n"
          "set palette defined (-18 '#f7fbff', -15 '#c6dbef', -12 '#6baed6', -9 '#fdd49e', -6 '#fc8d59', "
          "-3 '#d7301f', 0 '#7f0000', 1 '#7f0000', 1.01 'black', 2 'black')\n"
          "set bmargin 9\nset lmargin 18\n"
          "plot $cells using 1:2:3 with image notitle, "
          "$cells using 1:2:($3 > 1.5 ? 'NaN' : $3 >= 1 ? '≥1' : sprintf('%.0f', $3)):($3 > -4.5 ? 0xffffff : "
          "0x333333) "
          "with labels font ',7' tc rgb variable notitle\n")
      .render();
}

}  // namespace affinterp::plots
