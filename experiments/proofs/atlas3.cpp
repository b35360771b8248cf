#include "experiments/proofs/atlas3.hpp"

#include "theory/local/goodness3.hpp"

#include <array>
#include <map>
#include <stdexcept>

namespace affinterp::proofs {

namespace {

using logic::Polynomial;
using Rat = exact::Rational;

Polynomial symbol3(const std::string& name) { return Polynomial::variable(name); }

/// Lemma L16: det(I + tM) = 1 + c1 t + c2 t² + c3 t³; the derivative c1 + 2c2 t + 3c3 t² keeps one sign on [0, 1]
/// (≥ 0: at both ends, and at the vertex −c2/(3c3) when c3 > 0 puts it inside; ≤ 0 likewise).
constexpr const char* volume_condition =
    "(c1 >= 0 and c1 + 2*c2 + 3*c3 >= 0 and (c3 <= 0 or c2 >= 0 or c2 + 3*c3 <= 0 or c2^2 <= 3*c1*c3)) or "
    "(c1 <= 0 and c1 + 2*c2 + 3*c3 <= 0 and (c3 >= 0 or c2 <= 0 or c2 + 3*c3 >= 0 or c2^2 <= 3*c1*c3))";
constexpr const char* volume_words =
    "c1 + 2c2 t + 3c3 t² keeps one sign on [0, 1]: c1 and c1 + 2c2 + 3c3 of one sign (≥ 0 or ≤ 0), and where "
    "the vertex −c2/(3c3) lies in (0, 1) with the parabola opening away from that sign, c2² ≤ 3c1c3";
constexpr const char* semidefinite_condition = "(l1 >= 1 and l2 >= 1 and l3 >= 1) or (l1 <= 1 and l2 <= 1 and l3 <= 1)";
constexpr const char* semidefinite_words = "S − I semidefinite: all three eigenvalues of S on the same side of 1";

/// c1, c2, c3: the elementary symmetric functions of l1 − 1, l2 − 1, l3 − 1 (the invariants of S − I).
std::map<std::string, Polynomial> eigenvalue_macros() {
  const Polynomial m1 = symbol3("l1") - 1, m2 = symbol3("l2") - 1, m3 = symbol3("l3") - 1;
  return {{"c1", m1 + m2 + m3}, {"c2", m1 * m2 + m1 * m3 + m2 * m3}, {"c3", m1 * m2 * m3}};
}

Polynomial entry(int i, int j) { return symbol3("a" + std::to_string(i + 1) + std::to_string(j + 1)); }

Polynomial det3(const std::array<std::array<Polynomial, 3>, 3>& W) {
  return W[0][0] * (W[1][1] * W[2][2] - W[1][2] * W[2][1]) - W[0][1] * (W[1][0] * W[2][2] - W[1][2] * W[2][0]) +
         W[0][2] * (W[1][0] * W[2][1] - W[1][1] * W[2][0]);
}

/// P = sym(A) − I and Q = AᵀA − sym(A) = P + (A − I)ᵀ(A − I), entry by entry, with det A, det P and det Q.
std::map<std::string, Polynomial> linear_norm_macros() {
  std::map<std::string, Polynomial> macros;
  std::array<std::array<Polynomial, 3>, 3> A, P, Q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A[i][j] = entry(i, j);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Polynomial sym = Polynomial(Rat(1) / 2) * (A[i][j] + A[j][i]);
      Polynomial gram;
      for (int k = 0; k < 3; ++k) gram += A[k][i] * A[k][j];
      P[i][j] = sym - (i == j ? 1 : 0);
      Q[i][j] = gram - sym;
      const std::string index = std::to_string(i + 1) + std::to_string(j + 1);
      macros["p" + index] = P[i][j];
      macros["q" + index] = Q[i][j];
    }
  macros["det"] = det3(A);
  macros["detP"] = det3(P);
  macros["detQ"] = det3(Q);
  return macros;
}

constexpr const char* linear_norm_condition =
    "(p11 >= 0 and p22 >= 0 and p33 >= 0 and p11*p22 >= p12^2 and p11*p33 >= p13^2 and p22*p33 >= p23^2 and "
    "detP >= 0) or "
    "(q11 <= 0 and q22 <= 0 and q33 <= 0 and q11*q22 >= q12^2 and q11*q33 >= q13^2 and q22*q33 >= q23^2 and "
    "detQ <= 0)";

std::vector<AtlasCell> make_cells3() {
  const Polynomial c1 = symbol3("c1"), c2 = symbol3("c2"), c3 = symbol3("c3");
  const std::vector<std::string> invariants{"c1", "c2", "c3"}, eigenvalues{"l1", "l2", "l3"};
  std::vector<std::string> entries;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) entries.push_back("a" + std::to_string(i + 1) + std::to_string(j + 1));
  const std::map<std::string, Polynomial> none, eig = eigenvalue_macros(), lin = linear_norm_macros();
  const logic::Formula det_positive = logic::greater(Polynomial(1) + c1 + c2 + c3, 0);
  const logic::Formula positive =
      logic::greater(symbol3("l1"), 0) && logic::greater(symbol3("l2"), 0) && logic::greater(symbol3("l3"), 0);
  const std::string in_c = "c1, c2, c3 the invariants of M = A − I, with det A = 1 + c1 + c2 + c3 > 0";
  const std::string in_s = "l1, l2, l3 > 0 the eigenvalues of S (the singular values of A)";
  const auto cell = [](Homotopy h, Notion n, std::vector<std::string> vars, std::map<std::string, Polynomial> macros,
                       logic::Formula domain, std::string domain_words, std::string condition, std::string words) {
    return AtlasCell{h,
                     n,
                     std::move(vars),
                     std::move(macros),
                     std::move(domain),
                     std::move(domain_words),
                     std::move(condition),
                     std::move(words),
                     3};
  };
  return {
      cell(Homotopy::linear, Notion::volume, invariants, none, det_positive, in_c, volume_condition, volume_words),
      cell(Homotopy::linear, Notion::norm, entries, lin, logic::greater(lin.at("det"), 0),
           "A = [[a11, a12, a13], [a21, a22, a23], [a31, a32, a33]] real with det A > 0", linear_norm_condition,
           "sym(A) ⪰ I or AᵀA ⪯ sym(A) (Loewner order), as in 2D"),
      cell(Homotopy::svd, Notion::volume, eigenvalues, eig, positive, in_s, volume_condition, volume_words),
      cell(Homotopy::polar, Notion::volume, eigenvalues, eig, positive, in_s, volume_condition, volume_words),
      cell(Homotopy::polar, Notion::norm, eigenvalues, eig, positive, in_s, semidefinite_condition, semidefinite_words),
      cell(Homotopy::exp_log, Notion::volume, eigenvalues, eig, positive, in_s, "true",
           "always: det A(t) = (l1 l2 l3)^t"),
      cell(Homotopy::exp_log, Notion::norm, eigenvalues, eig, positive, in_s, semidefinite_condition,
           semidefinite_words),
  };
}

/// I + C, C the companion matrix of x³ − c1x² + c2x − c3: a map A whose A − I has the invariants c1, c2, c3.
local::Mat3<Rat> companion_map(const Rat& c1, const Rat& c2, const Rat& c3) {
  local::Mat3<Rat> B;
  B << Rat(1), Rat(0), c3, Rat(1), Rat(1), -c2, Rat(0), Rat(1), Rat(1) + c1;
  return B;
}

}  // namespace

const std::vector<AtlasCell>& atlas3_cells() {
  static const std::vector<AtlasCell> cells = make_cells3();
  return cells;
}

const AtlasCell& atlas3_cell(Homotopy h, Notion n) {
  for (const AtlasCell& c : atlas3_cells())
    if (c.homotopy == h && c.notion == n) return c;
  throw std::invalid_argument("the 3D atlas has no cell " + std::string(to_string(h)) + "." +
                              std::string(to_string(n)));
}

std::optional<bool> suite_says_good3(const AtlasCell& cell, const logic::Point& p) {
  const auto at = [&](const std::string& name) { return p.at(name); };
  if (cell.notion == Notion::singular_values) return std::nullopt;  // Lemma L25: nothing left to evaluate
  switch (cell.homotopy) {
    case Homotopy::linear:
      if (cell.notion == Notion::volume)
        return local::good_for_volume<Rat>(companion_map(at("c1"), at("c2"), at("c3")));
      {
        local::Mat3<Rat> A;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) A(i, j) = at("a" + std::to_string(i + 1) + std::to_string(j + 1));
        return local::good_for_norm_certified<Rat>(A);
      }
    case Homotopy::svd:
    case Homotopy::polar:
      if (cell.notion == Notion::volume)
        return local::good_for_volume<Rat>(local::diagonal3(at("l1"), at("l2"), at("l3")));
      return local::good_for_norm_polar<Rat>(at("l1"), at("l2"), at("l3"));
    case Homotopy::exp_log:
      if (cell.notion == Notion::volume) return std::nullopt;
      return local::good_for_norm_exp_log<Rat>(at("l1"), at("l2"), at("l3"));
  }
  return std::nullopt;
}

}  // namespace affinterp::proofs
