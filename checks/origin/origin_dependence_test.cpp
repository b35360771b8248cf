// Origin independence and dependence of the global energy (thesis §2.3, Problem 2.3.1).
#include "theory/origin/energy.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/symbols.hpp"
#include "theory/origin/two_triangles.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checks/origin/rational_gen.hpp"

namespace origin_dependence_test {

using namespace affinterp::origin;
using affinterp::origin::testing::origin_substitution;

namespace {

/// min over v of E2(A1, A2, B1(v), B2(v), o1, o2) at numeric origins.
GiNaC::ex min_E2(const TwoTriangles& config, const GiNaC::matrix& o1, const GiNaC::matrix& o2) {
  const Symbols& s = symbols();
  return minimise(energy_E2(config.A[0], config.A[1], intermediate_map(config, 0, s.v),
                            intermediate_map(config, 1, s.v), o1, o2),
                  s.unknowns)
      .value;
}

GiNaC::ex equal_energy_polynomial() {
  return locus_polynomial(thesis_study().min_E1.value - thesis_study().min_E2_common.value);
}

}  // namespace

RC_GTEST_PROP(OriginIndependence, AConformingTargetIsReachedWhateverTheOrigins,
              (GiNaC::numeric a, GiNaC::numeric b, GiNaC::numeric c, GiNaC::numeric d, GiNaC::numeric e,
               GiNaC::numeric f, GiNaC::numeric x1, GiNaC::numeric y1, GiNaC::numeric x2, GiNaC::numeric y2)) {
  // When both triangles follow one affine map M, v = M p makes B_i = M_i and every E2 is zero.
  TwoTriangles config = thesis_two_triangles();
  const GiNaC::matrix M{{a, b, c}, {d, e, f}, {0, 0, 1}};
  config.A = {M, M};
  RC_ASSERT(min_E2(config, column(x1, y1), column(x2, y2)).is_zero());
}

RC_GTEST_PROP(OriginDependence, EnergiesAgreeExactlyOnTheComputedLocus, (GiNaC::numeric x, GiNaC::numeric y)) {
  const GiNaC::ex at_o = min_E2(thesis_study().config, column(x, y), column(x, y));
  const bool on_locus = equal_energy_polynomial().subs(origin_substitution(x, y)).is_zero();
  const bool equal_energies = (at_o - thesis_study().min_E1.value).is_zero();
  RC_ASSERT(equal_energies == on_locus);
}

TEST(OriginDependence, RationalPointsOfTheLocusGiveEqualEnergies) {
  const auto points = small_rational_points(equal_energy_polynomial(), 8);
  ASSERT_GE(points.size(), 4u);
  for (const auto& [x, y] : points)
    EXPECT_TRUE((min_E2(thesis_study().config, column(x, y), column(x, y)) - thesis_study().min_E1.value).is_zero())
        << x << ", " << y;
}

TEST(OriginDependence, ThePrintedConicMissesTheOriginWhereTheEnergiesCoincideByDefinition) {
  EXPECT_TRUE((min_E2(thesis_study().config, column(0, 0), column(0, 0)) - thesis_study().min_E1.value).is_zero());
  EXPECT_FALSE((symbols().x * symbols().x - 4 * symbols().x * symbols().y + symbols().y * symbols().y + symbols().x +
                symbols().y - GiNaC::numeric(1, 4))
                   .subs(origin_substitution(0, 0))
                   .is_zero());
}

TEST(OriginDependence, MovingOnlyTheSecondOriginGivesAnotherMinimum) {
  // min E2(0, o) (the chapter introduction's set-up) and min E2(o, o) differ as rational functions of o.
  const Symbols& s = symbols();
  const GiNaC::ex split =
      minimise(energy_E2(thesis_study().config.A[0], thesis_study().config.A[1],
                         intermediate_map(thesis_study().config, 0, s.v),
                         intermediate_map(thesis_study().config, 1, s.v), column(0, 0), column(s.x, s.y)),
               s.unknowns)
          .value;
  EXPECT_FALSE((split - thesis_study().min_E2_common.value).normal().is_zero());
  EXPECT_TRUE((split - thesis_study().min_E2_common.value).subs(origin_substitution(0, 0)).is_zero());
}

RC_GTEST_PROP(OriginDependence, NoOriginsLetThePrintedTargetsBeMetExactly,
              (GiNaC::numeric x1, GiNaC::numeric y1, GiNaC::numeric x2, GiNaC::numeric y2)) {
  // A1 and A2 disagree on the shared edge, so no intermediate configuration has E2 = 0.
  RC_ASSERT(GiNaC::ex_to<GiNaC::numeric>(min_E2(thesis_study().config, column(x1, y1), column(x2, y2))).is_positive());
}

}  // namespace origin_dependence_test
