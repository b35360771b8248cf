#include "plots/origin/fig_2_6.hpp"

#include "plots/figure.hpp"
#include "plots/origin/triangle_outlines.hpp"
#include "theory/origin/symbols.hpp"

#include <string>

namespace affinterp::plots {
namespace {

constexpr double window = 3;  // the plane drawn: [−window, window]²
constexpr int cells = 120;

/// P(x, y) on a (cells + 1)² grid, as splot rows "x y P" with a blank line after each scan.
Table grid(const GiNaC::ex& P) {
  const origin::Symbols& s = origin::symbols();
  Table rows;
  for (int i = 0; i <= cells; ++i) {
    const double x = -window + 2 * window * i / cells;
    const GiNaC::ex in_y = P.subs(s.x == x);
    for (int j = 0; j <= cells; ++j) {
      const double y = -window + 2 * window * j / cells;
      rows.push_back({x, y, GiNaC::ex_to<GiNaC::numeric>(in_y.subs(s.y == y).evalf()).to_double()});
    }
    rows.push_back({});
  }
  return rows;
}

}  // namespace

std::vector<std::string> draw_fig_2_6(const std::filesystem::path& dir, const origin::TwoTriangles& config,
                                      const GiNaC::ex& computed_locus, const GiNaC::ex& printed_conic) {
  const Eigen::Matrix<double, 2, 4> p = source_vertices(config);
  return Figure(dir / "thesis-fig2.6")
      .size(760, 800)
      .data("computed", grid(computed_locus))
      .data("printed", grid(printed_conic))
      .data("T1", triangle_outline(config, 0, p))
      .data("T2", triangle_outline(config, 1, p))
      .script("W = " + std::to_string(window) + R"gp(
set contour base
set cntrparam levels discrete 0
unset surface
set view map
set table $computed_curve
splot $computed using 1:2:3 with lines
unset table
set table $printed_curve
splot $printed using 1:2:3 with lines
unset table
unset contour
set size ratio -1
set xrange [-W:W]
set yrange [-W:W]
set xlabel 'x'
set ylabel 'y'
set key below height 2
set title "Thesis Fig. 2.6: origins o = (x, y) with min E1 = min E2(o, o)"
plot $T1 with filledcurves closed fc rgb '#e8e8e8' notitle, \
     $T2 with filledcurves closed fc rgb '#d0d0d0' notitle, \
     $T1 with lines lc rgb '#777777' lw 1 title 'source triangles T1, T2', \
     $T2 with lines lc rgb '#777777' lw 1 notitle, \
     $computed_curve with lines lt 1 title 'computed: min E1 = min E2(o, o)', \
     $printed_curve with lines lt 2 dt 2 title 'printed: x^2 - 4xy + y^2 + x + y - 1/4 = 0', \
     '+' using (0):(0) every ::0::0 with points pt 7 ps 1.2 lc rgb '#000000' title 'o = 0 (E2 = E1 by definition)'
)gp")
      .render();
}

}  // namespace affinterp::plots
