// Kaji Fig. 1, recomputed: A = R_θ S with θ = π/2 and S = R_{−β} diag(8/5, 1/11) R_β (β = π/6), so that
// det A^P(t) = ((8/5 − 1)t + 1)((1/11 − 1)t + 1) vanishes at t = 1/(1 − 1/11) = 1.1 as in the paper.
#include "plots/local/figures.hpp"
#include "plots/triangles.hpp"
#include "theory/local/local.hpp"

#include <numbers>

namespace affinterp::plots {

std::vector<std::string> draw_kaji_figure_1(const std::filesystem::path& dir) {
  using affinterp::local::Mat2;
  using std::numbers::pi;
  const double theta = pi / 2, beta = pi / 6, lambda1 = 8.0 / 5, lambda2 = 1.0 / 11;
  const Mat2<double> S = affinterp::local::Svd<double>{-beta, lambda1, lambda2, beta}.matrix();
  const affinterp::local::PolarHomotopy<double> A_P{theta, S};
  const affinterp::local::ExpLogHomotopy<double> A_E(theta, S);

  Eigen::Matrix<double, 2, 3> p;  // the source triangle, centred on its centroid
  p << 0, 1, 0.3, 0, 0, 0.9;
  p.colwise() -= p.rowwise().mean();

  Table upright, flipped, labels, det_curves;
  constexpr int frames = 10;
  constexpr double spacing = 2.7, t_last = 1.35;
  for (int k = 0; k < frames; ++k) {
    const double t = t_last * k / (frames - 1);
    for (const auto& [row, homotopy_det, image] :
         {std::tuple{0.0, affinterp::local::det2(A_P(t)), Eigen::Matrix<double, 2, 3>(A_P(t) * p)},
          std::tuple{-3.0, affinterp::local::det2(A_E(t)), Eigen::Matrix<double, 2, 3>(A_E(t) * p)}})
      append_triangle(homotopy_det >= 0 ? upright : flipped, image, Eigen::Vector2d(spacing * k, row), t);
    labels.push_back({spacing * k, 1.7, t});
  }
  for (int j = 0; j <= 270; ++j) {
    const double t = t_last * j / 270;
    det_curves.push_back({t, affinterp::local::det2(A_P(t)), affinterp::local::det2(A_E(t))});
  }

  const std::string name = "kaji-fig1";
  return Figure(dir / name)
      .size(1300, 820)
      .data("upright", upright)
      .data("flipped", flipped)
      .data("labels", labels)
      .data("det", det_curves)
      .script(
          "set multiplot\n"
          "set size 1, 0.6\nset origin 0, 0.4\n"
          "set title 'Kaji Fig. 1: t = 0 ... 1.35; top: polar homotopy A^P(t) (eq. 2), bottom: exp-log homotopy A^E(t) "
          "(eq. 3)'\n"
          "set size ratio -1\nunset xtics\nunset ytics\nunset grid\nunset border\n"
          "set xrange [-1.4:25.8]\nset yrange [-4.6:2.1]\n"
          "set label 1 'A^P' at -1.3, 0 left font ',13'\nset label 2 'A^E' at -1.3, -3 left font ',13'\n"
          "plot $upright using 1:2 with filledcurves closed fc rgb '#9ecae1' notitle, \\\n"
          "     $flipped using 1:2 with filledcurves closed fc rgb '#fdae6b' notitle, \\\n"
          "     $upright using 1:2 with lines lc rgb '#08519c' lw 1.5 notitle, \\\n"
          "     $flipped using 1:2 with lines lc rgb '#a63603' lw 1.5 notitle, \\\n"
          "     $labels using 1:2:(sprintf('t = %.2f', $3)) with labels font ',10' notitle\n"
          "unset label 1\nunset label 2\n"
          "set size 1, 0.4\nset origin 0, 0\nset size noratio\nset border\nset grid\nset xtics\nset ytics\n"
          "set autoscale\nset xrange [0:1.35]\nset title 'det A(t): the polar homotopy collapses at t = 1.1 and turns "
          "over (orange); the exp-log one stays positive'\n"
          "set xlabel 't'\nset ylabel 'det A(t)'\nset key bottom left box opaque\nset arrow 1 from 1.1, graph 0 to "
          "1.1, graph 1 nohead dt 2 lc rgb '#777777'\n"
          "plot $det using 1:2 with lines lt 2 title 'det A^P(t) = ((λ_1-1)t+1)((λ_2-1)t+1)', \\\n"
          "     $det using 1:3 with lines lt 1 title 'det A^E(t) = (λ_1 λ_2)^t', 0 with lines lc rgb '#555555' lw 1 "
          "notitle\n"
          "unset multiplot\n")
      .render();
}

}  // namespace affinterp::plots
