// thesis Figs 2.2–2.5, recomputed: the example of §2.2.4, P = ((0,0), (0,3), (2,0)) onto
// Q = ((0,0), (−9√3/4, −15/4), (−1/2, 3√3/2)), interpolated with the printed decompositions
// (SVD α = π/3, D = diag(2, 1), β = −5π/3; polar γ = −4π/3), at t = 0, 0.1, ..., 1.
#include "plots/local/figures.hpp"
#include "plots/triangles.hpp"
#include "theory/local/local.hpp"

#include <cmath>
#include <functional>
#include <numbers>

namespace affinterp::plots {

std::vector<std::string> draw_thesis_figures_2_2_to_2_5(const std::filesystem::path& dir) {
  using affinterp::local::Mat2;
  using std::numbers::pi;
  const double r3 = std::sqrt(3.0);
  Mat2<double> A, S;
  A << -0.25, -0.75 * r3, 0.75 * r3, -1.25;
  S << 1.25, -0.25 * r3, -0.25 * r3, 1.75;
  const affinterp::local::LinearHomotopy<double> A_l{A};
  const affinterp::local::SvdHomotopy<double> A_s{{pi / 3, 2, 1, -5 * pi / 3}};
  const affinterp::local::PolarHomotopy<double> A_p{-4 * pi / 3, S};
  Eigen::Matrix<double, 2, 3> P;
  P << 0, 0, 2, 0, 3, 0;

  const std::vector<std::pair<std::string, std::function<Mat2<double>(double)>>> methods = {
      {"linear", A_l}, {"SVD", A_s}, {"polar", A_p}};
  std::vector<Table> frames(methods.size());
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (int k = 0; k <= 10; ++k)
      append_triangle(frames[m], methods[m].second(k / 10.0) * P, Eigen::Vector2d::Zero(), k / 10.0);

  const std::string triangles = "thesis-fig2.2-2.4";
  Figure figure(dir / triangles);
  figure.size(1500, 560);
  std::string script =
      "set multiplot layout 1,3 title 'thesis Figs 2.2-2.4: P to Q by linear, SVD and polar interpolation, t = 0 "
      "(blue), 0.1, ..., 1 (red)'\n"
      "set size ratio -1\nset xrange [-4.8:4.8]\nset yrange [-5.2:3.4]\nset palette defined (0 '#2166ac', 0.5 "
      "'#999999', 1 '#b2182b')\n"
      "set cbrange [0:1]\nunset colorbox\n";
  const std::vector<std::string> titles = {"Fig 2.2: linear A_l(t)", "Fig 2.3: SVD A_s(t), α = π/3, β = -5π/3",
                                           "Fig 2.4: polar A_p(t), γ = -4π/3"};
  for (std::size_t m = 0; m < methods.size(); ++m) {
    figure.data(methods[m].first, frames[m]);
    script += "set title '" + titles[m] + "'\nplot $" + methods[m].first +
              " using 1:2:3 with lines lc palette lw 1.5 notitle\n";
  }
  std::vector<std::string> files = figure.script(script + "unset multiplot\n").render();

  Table det_curves;
  for (int j = 0; j <= 200; ++j) {
    const double t = j / 200.0;
    det_curves.push_back(
        {t, affinterp::local::det2(A_l(t)), affinterp::local::det2(A_s(t)), affinterp::local::det2(A_p(t))});
  }
  const std::string det_name = "thesis-fig2.5";
  for (std::string& file :
       Figure(dir / det_name)
           .size(900, 560)
           .data("det", det_curves)
           .script(
               "set title 'thesis Fig. 2.5: det A_l(t) of the linear interpolation (not monotone: not good for area)'\n"
               "set xlabel 't'\nset ylabel 'det A(t)'\nset key top left\nset yrange [0:*]\n"
               "plot $det using 1:2 with lines lt 2 title 'det A_l(t) = 9/2 t^2 - 7/2 t + 1', \\\n"
               "     $det using 1:3 with lines lt 1 title 'det A_s(t) = 1 + t', \\\n"
               "     $det using 1:4 with lines lt 3 dt 2 title 'det A_p(t) = 1 + t'\n")
           .render())
    files.push_back(std::move(file));
  return files;
}

}  // namespace affinterp::plots
