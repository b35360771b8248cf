#include "plots/origin/triangle_outlines.hpp"

namespace affinterp::plots {

Table triangle_outline(const origin::TwoTriangles& config, unsigned i, const Eigen::Matrix<double, 2, 4>& v) {
  Table outline;
  for (unsigned c = 0; c <= 3; ++c) {
    const unsigned k = config.triangles[i][c % 3];
    outline.push_back({v(0, k), v(1, k)});
  }
  return outline;
}

Eigen::Matrix<double, 2, 4> source_vertices(const origin::TwoTriangles& config) {
  Eigen::Matrix<double, 2, 4> p;
  for (unsigned k = 0; k < 4; ++k)
    for (unsigned r = 0; r < 2; ++r) p(r, k) = GiNaC::ex_to<GiNaC::numeric>(config.source(r, k).evalf()).to_double();
  return p;
}

}  // namespace affinterp::plots
