#include "experiments/proofs/atlas.hpp"

#include "experiments/proofs/atlas3.hpp"
#include "theory/local/goodness.hpp"
#include "theory/logic/condition_parser.hpp"

#include <stdexcept>

namespace affinterp::proofs {

namespace {

using logic::Polynomial;

Polynomial var(const char* name) { return Polynomial::variable(name); }

/// Thm 2.2.1 as corrected (claims.json): det A(t) is positive and monotone on [0, 1].
constexpr const char* area_condition = "(2*det <= tr and tr <= 2) or (2 <= tr and tr <= 2*det)";
constexpr const char* area_words = "2 det ≤ tr ≤ 2 or 2 ≤ tr ≤ 2 det";

std::vector<AtlasCell> make_cells() {
  const Polynomial a = var("a"), b = var("b"), c = var("c"), d = var("d"), x = var("x"), y = var("y"), h = var("h");
  const std::map<std::string, Polynomial> linear_macros{{"tr", a + d}, {"det", a * d - b * c}};
  const std::map<std::string, Polynomial> diagonal_macros{{"tr", x + y}, {"det", x * y}};
  const std::map<std::string, Polynomial> symmetric_macros{{"tr", x + y}, {"det", x * y - h * h}};
  const logic::Formula gl_plus = logic::greater(a * d - b * c, 0);
  const logic::Formula positive_diagonal = logic::greater(x, 0) && logic::greater(y, 0);
  const logic::Formula positive_definite =
      logic::greater(x, 0) && logic::greater(y, 0) && logic::greater(x * y - h * h, 0);
  const std::vector<std::string> linear{"a", "b", "c", "d"}, diagonal{"x", "y"}, svd_norm{"x", "y", "beta"},
      symmetric{"x", "y", "h"};
  const std::string in_gl = "A = [[a, b], [c, d]] real with det A > 0";
  const std::string in_diag = "D = diag(x, y) with x, y > 0";
  const std::string in_spd = "S = [[x, h], [h, y]] symmetric positive definite";
  const char* polar_norm = "(x - 1)*(y - 1) >= h^2";
  return {
      {Homotopy::linear, Notion::area, linear, linear_macros, gl_plus, in_gl, area_condition, area_words},
      {Homotopy::linear, Notion::norm, linear, linear_macros, gl_plus, in_gl,
       "(a >= 1 and d >= 1 and 4*(a - 1)*(d - 1) >= (b + c)^2) or "
       "(a - a^2 - c^2 >= 0 and d - b^2 - d^2 >= 0 and "
       "4*(a - a^2 - c^2)*(d - b^2 - d^2) >= (b + c - 2*a*b - 2*c*d)^2)",
       "sym(A) ⪰ I or AᵀA ⪯ sym(A) (Loewner order; equivalently ‖A − I/2‖₂ ≤ 1/2 in the second case)"},
      {Homotopy::svd, Notion::area, diagonal, diagonal_macros, positive_diagonal, in_diag, area_condition, area_words},
      {Homotopy::svd, Notion::norm, svd_norm, diagonal_macros, positive_diagonal, in_diag + ", β real",
       "beta^2*(x - y)^2*(x + y)^2 <= 4*x*y*(x - 1)*(y - 1)",
       "β²(x − y)²(x + y)² ≤ 4xy(x − 1)(y − 1), β the right rotation's angle in radians"},
      {Homotopy::polar, Notion::area, symmetric, symmetric_macros, positive_definite, in_spd, area_condition,
       area_words},
      {Homotopy::polar, Notion::norm, symmetric, symmetric_macros, positive_definite, in_spd, polar_norm,
       "det(S − I) ≥ 0: both eigenvalues of S on the same side of 1"},
      {Homotopy::exp_log, Notion::area, symmetric, symmetric_macros, positive_definite, in_spd, "true",
       "always: det A(t) = (det S)^t"},
      {Homotopy::exp_log, Notion::norm, symmetric, symmetric_macros, positive_definite, in_spd, polar_norm,
       "det(S − I) ≥ 0: both eigenvalues of S on the same side of 1"},
  };
}

using local::Mat2;
using Q = exact::Rational;

Mat2<Q> matrix(const Q& m00, const Q& m01, const Q& m10, const Q& m11) {
  Mat2<Q> m;
  m << m00, m01, m10, m11;
  return m;
}

}  // namespace

std::string_view to_string(Homotopy h) {
  switch (h) {
    case Homotopy::linear:
      return "linear";
    case Homotopy::svd:
      return "svd";
    case Homotopy::polar:
      return "polar";
    case Homotopy::exp_log:
      return "exp-log";
  }
  return "?";
}

std::string_view to_string(Notion n) {
  switch (n) {
    case Notion::area:
      return "area";
    case Notion::norm:
      return "norm";
    case Notion::volume:
      return "volume";
    case Notion::singular_values:
      return "singular-values";
  }
  return "?";
}

std::string AtlasCell::id() const { return std::string(to_string(homotopy)) + "." + std::string(to_string(notion)); }

logic::Formula AtlasCell::condition_formula() const { return logic::parse_condition(condition, variables, macros); }

const std::vector<AtlasCell>& atlas_cells() {
  static const std::vector<AtlasCell> cells = make_cells();
  return cells;
}

const AtlasCell& atlas_cell(Homotopy h, Notion n) {
  for (const AtlasCell& c : atlas_cells())
    if (c.homotopy == h && c.notion == n) return c;
  throw std::logic_error("no atlas cell");
}

std::optional<bool> suite_says_good(const AtlasCell& cell, const logic::Point& p) {
  if (!logic::holds(cell.domain, p)) throw std::invalid_argument("suite_says_good(): outside the domain");
  if (cell.dimension == 3) return suite_says_good3(cell, p);
  const auto at = [&](const char* name) { return p.at(name); };
  std::optional<Mat2<Q>> B;  // A(t) = U(t)((1−t)I + tB)V(t) with det- and norm-preserving U, V
  switch (cell.homotopy) {
    case Homotopy::linear:
      B = matrix(at("a"), at("b"), at("c"), at("d"));
      break;
    case Homotopy::polar:
      B = matrix(at("x"), at("h"), at("h"), at("y"));
      break;
    case Homotopy::svd:
      if (cell.notion == Notion::area) B = matrix(at("x"), 0, 0, at("y"));
      break;
    case Homotopy::exp_log:
      break;
  }
  if (!B) return std::nullopt;
  return cell.notion == Notion::area ? local::good_for_area<Q>(*B) : local::good_for_norm<Q>(*B);
}

}  // namespace affinterp::proofs
