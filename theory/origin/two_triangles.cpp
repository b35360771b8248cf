#include "theory/origin/two_triangles.hpp"

#include "theory/origin/affine_frames.hpp"
#include "theory/origin/printed_section_2_3.hpp"
#include "theory/origin/symbols.hpp"

namespace affinterp::origin {

TwoTriangles thesis_two_triangles() {
  TwoTriangles config;
  config.source = GiNaC::matrix{{0, 1, 0, 1}, {0, 0, 1, 1}};
  const GiNaC::exmap at_zero{{symbols().x, 0}, {symbols().y, 0}};
  config.A = {GiNaC::ex_to<GiNaC::matrix>(printed::A1().subs(at_zero)),
              GiNaC::ex_to<GiNaC::matrix>(printed::A2().subs(at_zero))};
  return config;
}

GiNaC::matrix triangle_corners(const TwoTriangles& config, unsigned i, const GiNaC::matrix& vertices) {
  GiNaC::matrix corners(2, 3);
  for (unsigned c = 0; c < 3; ++c)
    for (unsigned r = 0; r < 2; ++r) corners(r, c) = vertices(r, config.triangles[i][c]);
  return corners;
}

GiNaC::matrix intermediate_map(const TwoTriangles& config, unsigned i, const GiNaC::matrix& v) {
  return affine_map(triangle_corners(config, i, config.source), triangle_corners(config, i, v));
}

GiNaC::matrix barycentre(const TwoTriangles& config, unsigned i) {
  const GiNaC::matrix corners = triangle_corners(config, i, config.source);
  const GiNaC::numeric third(1, 3);
  return column(third * (corners(0, 0) + corners(0, 1) + corners(0, 2)),
                third * (corners(1, 0) + corners(1, 1) + corners(1, 2)));
}

GiNaC::matrix apply(const GiNaC::matrix& A, const GiNaC::matrix& p) {
  return linear_part(A).mul(p).add(translation(A));
}

}  // namespace affinterp::origin
