#include "theory/origin/affine_frames.hpp"
#include "theory/origin/symbols.hpp"
#include "theory/origin/two_triangles.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checks/origin/rational_gen.hpp"

namespace affine_frames_test {

using namespace affinterp::origin;

namespace {

GiNaC::matrix corners(const GiNaC::numeric& a, const GiNaC::numeric& b, const GiNaC::numeric& c,
                      const GiNaC::numeric& d, const GiNaC::numeric& e, const GiNaC::numeric& f) {
  return GiNaC::matrix{{a, c, e}, {b, d, f}};
}

}  // namespace

TEST(AffineMap, IsKajiEquationOneForTheUnitTriangle) {
  const GiNaC::matrix P{{0, 1, 0}, {0, 0, 1}}, Q{{3, 5, 4}, {1, 1, 7}};
  const GiNaC::matrix A = affine_map(P, Q);
  EXPECT_TRUE(is_zero_matrix(A.sub(GiNaC::matrix{{2, 1, 3}, {0, 6, 1}, {0, 0, 1}})));
}

RC_GTEST_PROP(AffineMap, SendsEachCornerOntoItsImage,
              (GiNaC::numeric a, GiNaC::numeric b, GiNaC::numeric c, GiNaC::numeric d, GiNaC::numeric e,
               GiNaC::numeric f, GiNaC::numeric g, GiNaC::numeric h)) {
  const GiNaC::matrix P = corners(0, 0, 1, 0, a, 1 + b * b);  // non-degenerate: third corner off the x-axis
  const GiNaC::matrix Q = corners(c, d, e, f, g, h);
  const GiNaC::matrix A = affine_map(P, Q);
  for (unsigned k = 0; k < 3; ++k)
    RC_ASSERT(is_zero_matrix(apply(A, column(P(0, k), P(1, k))).sub(column(Q(0, k), Q(1, k)))));
  RC_ASSERT(A(2, 0).is_zero() && A(2, 1).is_zero() && (A(2, 2) - 1).is_zero());
}

RC_GTEST_PROP(TranslateOrigin, IsAConjugationThatKeepsTheLinearPart,
              (GiNaC::numeric a, GiNaC::numeric b, GiNaC::numeric c, GiNaC::numeric d, GiNaC::numeric e,
               GiNaC::numeric f, GiNaC::numeric x, GiNaC::numeric y)) {
  const GiNaC::matrix A{{a, b, c}, {d, e, f}, {0, 0, 1}};
  const GiNaC::matrix o = column(x, y);
  const GiNaC::matrix moved = translate_origin(A, o);
  RC_ASSERT(is_zero_matrix(linear_part(moved).sub(linear_part(A))));
  RC_ASSERT(is_zero_matrix(translate_origin(moved, o.mul_scalar(-1)).sub(A)));
  // T(A, o) is p ↦ A(p − o) + o: it fixes o exactly when A fixes the world origin.
  RC_ASSERT(is_zero_matrix(apply(moved, o).sub(apply(A, column(0, 0)).add(o))));
}

TEST(TranslateOrigin, WritesAMapAboutTheOriginO) {
  // In coordinates centred at o, the map is T(A, −o): it sends p − o to A(p) − o.
  const GiNaC::matrix A{{2, 1, 3}, {0, 6, 1}, {0, 0, 1}};
  const GiNaC::matrix o = column(5, -2), p = column(7, 3);
  EXPECT_TRUE(is_zero_matrix(apply(translate_origin(A, o.mul_scalar(-1)), p.sub(o)).sub(apply(A, p).sub(o))));
}

}  // namespace affine_frames_test
