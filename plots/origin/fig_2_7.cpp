#include "plots/origin/fig_2_7.hpp"

#include "plots/figure.hpp"
#include "plots/origin/triangle_outlines.hpp"
#include "theory/origin/frame_interpolation.hpp"
#include "theory/origin/symbols.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <sstream>

namespace affinterp::plots {
namespace {

constexpr int frames = 5;

Eigen::Vector2d to_vector(const GiNaC::matrix& column) {
  return {GiNaC::ex_to<GiNaC::numeric>(column(0, 0).evalf()).to_double(),
          GiNaC::ex_to<GiNaC::numeric>(column(1, 0).evalf()).to_double()};
}

/// The target triangle A_i(T_i), from the world-coordinate map A_i.
Table target_outline(const origin::TwoTriangles& config, unsigned i) {
  Eigen::Matrix<double, 2, 4> q;
  for (unsigned k = 0; k < 4; ++k)
    q.col(k) = to_vector(origin::apply(config.A[i], origin::column(config.source(0, k), config.source(1, k))));
  return triangle_outline(config, i, q);
}

}  // namespace

Fig27 draw_fig_2_7(const std::filesystem::path& dir, const origin::TwoTriangles& config) {
  const std::array<Eigen::Vector2d, 2> at_zero{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  const std::array<Eigen::Vector2d, 2> at_barycentres{to_vector(origin::barycentre(config, 0)),
                                                      to_vector(origin::barycentre(config, 1))};
  Figure figure(dir / "thesis-fig2.7");
  Fig27 result;
  std::ostringstream script;
  Eigen::AlignedBox2d box;
  for (int f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / (frames - 1);
    const Eigen::Matrix<double, 2, 4> red = origin::global_interpolation(config, at_zero, t);
    const Eigen::Matrix<double, 2, 4> green = origin::global_interpolation(config, at_barycentres, t);
    result.largest_gap = std::max(result.largest_gap, (red - green).colwise().norm().maxCoeff());
    for (unsigned k = 0; k < 4; ++k) box.extend(red.col(k)).extend(green.col(k));
    for (unsigned i = 0; i < 2; ++i) {
      figure.data("red" + std::to_string(f) + "_" + std::to_string(i), triangle_outline(config, i, red));
      figure.data("green" + std::to_string(f) + "_" + std::to_string(i), triangle_outline(config, i, green));
    }
  }
  for (unsigned i = 0; i < 2; ++i) {
    const Table target = target_outline(config, i);
    for (const Row& row : target) box.extend(Eigen::Vector2d(row[0], row[1]));
    figure.data("target" + std::to_string(i), target);
  }
  const Eigen::Vector2d lo = box.min().array() - 0.3, hi = box.max().array() + 0.3;
  script << "set multiplot layout 1," << frames
         << " title \"Thesis Fig. 2.7: global interpolation, red: origins at zero, green: origins at the "
            "barycentres (dashed: A_1(T_1), A_2(T_2))\"\n"
         << "set size ratio -1\nunset key\nset xtics 1\nset ytics 1\n"
         << "set xrange [" << lo.x() << ":" << hi.x() << "]\nset yrange [" << lo.y() << ":" << hi.y() << "]\n";
  for (int f = 0; f < frames; ++f) {
    script << "set title 't = " << static_cast<double>(f) / (frames - 1) << "'\nplot ";
    if (f == frames - 1)
      script << "$target0 with lines lc rgb '#777777' lw 1 dt 2, $target1 with lines lc rgb '#777777' lw 1 dt 2, ";
    for (unsigned i = 0; i < 2; ++i)
      script << "$red" << f << "_" << i << " with lines lc rgb '#d62728' lw 2, $green" << f << "_" << i
             << " with lines lc rgb '#2ca02c' lw 2" << (i == 0 ? ", " : "\n");
  }
  script << "unset multiplot\n";
  result.files = figure.size(1500, 520).script(script.str()).render();
  return result;
}

}  // namespace affinterp::plots
