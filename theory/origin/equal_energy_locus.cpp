#include "theory/origin/equal_energy_locus.hpp"

#include "theory/origin/symbols.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace affinterp::origin {

OriginStudy study_origin(const TwoTriangles& config) {
  const Symbols& s = symbols();
  const GiNaC::matrix o = column(s.x, s.y);
  const GiNaC::matrix B1 = intermediate_map(config, 0, s.v), B2 = intermediate_map(config, 1, s.v);
  OriginStudy study{
      config, energy_E1(config.A[0], config.A[1], B1, B2), energy_E2(config.A[0], config.A[1], B1, B2, o, o), {}, {}};
  study.min_E1 = minimise(study.E1, s.unknowns);
  study.min_E2_common = minimise(study.E2_common, s.unknowns);
  return study;
}

const OriginStudy& thesis_study() {
  static const OriginStudy study = study_origin(thesis_two_triangles());
  return study;
}

GiNaC::ex locus_polynomial(const GiNaC::ex& difference) {
  const Symbols& s = symbols();
  GiNaC::ex P = GiNaC::numer(difference.normal()).expand();
  if (P.is_zero()) return P;
  P = (P / P.integer_content()).expand();
  const GiNaC::ex leading = P.lcoeff(s.x).expand().lcoeff(s.y);
  if (GiNaC::ex_to<GiNaC::numeric>(leading).is_negative()) P = (-P).expand();
  return P;
}

int total_degree(const GiNaC::ex& P) {
  const Symbols& s = symbols();
  const GiNaC::ex e = P.expand();
  int degree = -1;
  for (int i = 0; i <= e.degree(s.x); ++i) {
    const GiNaC::ex in_y = e.coeff(s.x, i);
    if (!in_y.is_zero()) degree = std::max(degree, i + in_y.degree(s.y));
  }
  return degree;
}

bool proportional(const GiNaC::ex& P, const GiNaC::ex& Q) {
  if (P.is_zero() || Q.is_zero()) return false;
  const GiNaC::ex ratio = (P / Q).normal();
  return GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero();
}

std::vector<std::pair<GiNaC::numeric, GiNaC::numeric>> small_rational_points(const GiNaC::ex& P, std::size_t count) {
  const Symbols& s = symbols();
  if (P.expand().degree(s.y) > 2) throw std::invalid_argument("small_rational_points: degree in y above 2");
  std::vector<std::pair<GiNaC::numeric, GiNaC::numeric>> points;
  for (long q = 1; q <= 4; ++q)
    for (long magnitude = 0; magnitude <= 2 * q; ++magnitude)
      for (long sign : {1, -1}) {
        if (magnitude == 0 && sign < 0) continue;
        const GiNaC::numeric x(sign * magnitude, q);
        if (x.denom() != q) continue;  // already visited with a smaller denominator
        const GiNaC::ex in_y = P.subs(s.x == x).expand();
        const GiNaC::numeric a = GiNaC::ex_to<GiNaC::numeric>(in_y.coeff(s.y, 2));
        const GiNaC::numeric b = GiNaC::ex_to<GiNaC::numeric>(in_y.coeff(s.y, 1));
        const GiNaC::numeric c = GiNaC::ex_to<GiNaC::numeric>(in_y.coeff(s.y, 0));
        std::vector<GiNaC::numeric> roots;
        if (a.is_zero()) {
          if (!b.is_zero()) roots.push_back(-c / b);
        } else {
          const GiNaC::numeric discriminant = b * b - 4 * a * c;
          const GiNaC::numeric root = GiNaC::sqrt(discriminant);
          if (!discriminant.is_negative() && root.is_rational()) {
            roots.push_back((-b + root) / (2 * a));
            if (!root.is_zero()) roots.push_back((-b - root) / (2 * a));
          }
        }
        for (const GiNaC::numeric& y : roots) {
          if (points.size() == count) return points;
          points.emplace_back(x, y);
        }
      }
  return points;
}

bool positive_quadratic(const GiNaC::ex& q) {
  const Symbols& s = symbols();
  const GiNaC::ex e = q.expand();
  if (e.degree(s.x) > 2 || e.degree(s.y) > 2 || e.coeff(s.x, 2).degree(s.y) > 0 || e.coeff(s.x, 1).degree(s.y) > 1)
    return false;
  // q = a x² + b xy + c y² + d x + f y + g.
  const std::array<GiNaC::ex, 6> coefficients = {e.coeff(s.x, 2),
                                                 e.coeff(s.x, 1).coeff(s.y, 1),
                                                 e.coeff(s.x, 0).coeff(s.y, 2),
                                                 e.coeff(s.x, 1).coeff(s.y, 0),
                                                 e.coeff(s.x, 0).coeff(s.y, 1),
                                                 e.coeff(s.x, 0).coeff(s.y, 0)};
  for (const GiNaC::ex& coefficient : coefficients)
    if (!GiNaC::is_a<GiNaC::numeric>(coefficient)) return false;
  const auto n = [&](int k) { return GiNaC::ex_to<GiNaC::numeric>(coefficients[k]); };
  const GiNaC::numeric a = n(0), b = n(1), c = n(2), d = n(3), f = n(4), g = n(5);
  // r2 t² + r1 t + r0 > 0 for every real t.
  const auto positive_in_one_variable = [](const GiNaC::numeric& r2, const GiNaC::numeric& r1,
                                           const GiNaC::numeric& r0) {
    if (r2.is_zero()) return r1.is_zero() && r0.is_positive();
    return r2.is_positive() && (r1 * r1 - 4 * r2 * r0).is_negative();
  };
  // With a > 0, q = a (x + (b y + d) / 2a)² + r(y): positive everywhere iff r is. With a = 0, q is
  // unbounded below unless it does not depend on x.
  if (a.is_zero()) return b.is_zero() && d.is_zero() && positive_in_one_variable(c, f, g);
  if (a.is_negative()) return false;
  return positive_in_one_variable(c - b * b / (4 * a), f - b * d / (2 * a), g - d * d / (4 * a));
}

}  // namespace affinterp::origin
