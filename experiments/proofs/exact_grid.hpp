#pragma once
// The second checker of a polynomial or rational identity lhs = rhs, sharing no arithmetic with
// GiNaC's normal(): both sides are read as the expression trees the suite's algebra built (sums, products,
// integer powers, rational numbers, symbols; a function such as exp(λ) is an independent variable), each
// turned into a fraction n/d without cancelling anything, and the numerator N = n_l d_r − n_r d_l of the
// difference is evaluated exactly (integers) on the points S = {a ∈ ℕ^k : a_i ≤ d_i, Σ a_i ≤ T}, d_i a structural
// bound on N's degree in variable i and T one on its total degree (both by the same rules: sums max(n1 + d2,
// n2 + d1); products add; powers n ×). A polynomial whose monomials x^a all have a in S and that vanishes on S is
// the zero polynomial: S is closed downwards, so N is a combination Σ_{a∈S} c_a Π_i x_i(x_i − 1)…(x_i − a_i + 1)
// of falling factorials; that product is nonzero at the point b ∈ S iff a ≤ b componentwise, so at a minimal a
// with c_a ≠ 0, N(a) = c_a Π_i a_i! ≠ 0. (Without T, S is the box ∏_i {0, …, d_i} of N. Alon, Combinatorial
// Nullstellensatz, Combin. Probab. Comput. 8 (1999), Lemma 2.1.) So N vanishing on S proves lhs = rhs wherever
// both sides are defined, provided neither denominator is the zero polynomial, which S shows too (their bounds are
// below d_i and T).
//
// The steps an identity carries (step_nodes.hpp) are performed here, on the same fractions:
//   derivative d/dx e    dual numbers: every value is a jet a_0 + Σ a_m ε^m in ε_0, ε_1 (ε_j² = 0, one ε per
//                        nesting level of derivatives), the symbol x inside d/dx evaluated as x + ε_j; the sums,
//                        products and powers above then carry the exact derivatives of n and d (product rule), and
//                        d/dx (n/d) = (n' d − n d')/d² (quotient rule). Bounds: each bound holds for every
//                        coefficient of a jet; deg(n' d − n d') ≤ deg n + deg d, less one in x and in total when
//                        all of e's dependence on the grid's x passes through ε_j (x not substituted around the
//                        derivative, nor brought in by a substituted value): then n' = ∂n/∂x. The denominator d²
//                        has twice d's bounds.
//   substitution e|x=v   v evaluated as a fraction where the substitution stands, and x inside e read as v (with
//                        its n and d bounds in place of x's degree 1); x is then no grid variable inside e.
//   matrices             a product's entries are the sums Σ_k A_ik B_kj of products of the factors' entries, a
//                        transpose swaps indices, a determinant (at most 4 × 4) is Leibniz's signed sum
//                        Σ_σ sgn σ Π_i M_iσ(i): sums and products of fractions, bounded as above.
//   functions            f(g) is an independent grid variable F, named by f and g expanded by the grid's own
//                        polynomial arithmetic with the open substitutions applied (expanded_polynomial.hpp: cos(φ +
//                        tβ) at t = 0 is the variable cos(φ)). Under d/dt with t in g, f = cos, sin, exp follow the
//                        chain rule to second order with P its partner (sin, cos, exp) another grid variable: with
//                        h = g − g(0 ε), cos(g) = F(1 − h²/2) − P h, sin(g) = F(1 − h²/2) + P h, exp(g) = F(1 + h +
//                        h²/2). So the grid decides an identity in independent F, P, …; it holds for F = cos g,
//                        P = sin g in particular, and these jets are what the derivation d/dt with dF = −P dg,
//                        dP = F dg gives, which the chain rule makes d/dt of the functions themselves. No degree is
//                        lowered under such a derivative (F does not depend on t on the grid, its jet does). Other
//                        functions, non-polynomial arguments, and a function of a number after a substitution
//                        (cos 0: the grid does not know it is 1) are refused.
// Each is exact polynomial arithmetic on n and d, so N stays a polynomial whose degrees the bounds dominate, and
// the lemma above applies as before.
// What it shares with GiNaC is the tree: GiNaC's constructors flatten sums and products, collect numeric
// coefficients of equal terms and combine equal factors (x·x⁻¹ = 1), but never expand a product or a power of a
// sum and never cancel a common factor that is not literally equal; they perform none of the steps. The two
// sides are read separately, so nothing cancels between them before the grid evaluates N.
#include <ginac/ginac.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace affinterp::proofs {

struct GridVerdict {
  bool zero = false;  ///< N vanished on the whole grid: the identity holds
  /// Variable (a symbol's name, or a function such as exp(L1) read as a variable) → d_i, grid {0, …, d_i}.
  std::vector<std::pair<std::string, unsigned>> degree_bounds;
  unsigned total_degree = 0;      ///< T
  std::uint64_t grid_points = 0;  ///< |S|
  std::uint64_t evaluated = 0;    ///< points evaluated (all of them when zero)
  /// The first grid point where N ≠ 0, by variable, and N there (as text), when not zero.
  std::map<std::string, unsigned> witness;
  std::string witness_value;
};

/// Decides lhs = rhs (scalars, or matrices of the same shape entry by entry) on the grid, performing their steps.
/// Throws std::invalid_argument on an expression that is not rational in its variables (a non-integer power or a
/// non-rational number), on a step it cannot perform (derivatives nested more than twice, a step on a symbol
/// inside a function, a determinant larger than 4 × 4), on a grid of more than `max_points` points, and on a
/// denominator that is the zero polynomial.
GridVerdict grid_check(const GiNaC::ex& lhs, const GiNaC::ex& rhs, std::uint64_t max_points = 20'000'000);

/// The verdict as the lines of a <name>.grid.out file: the lemma, the bounds, the grid and the result.
std::string to_text(const GridVerdict& verdict);

}  // namespace affinterp::proofs
