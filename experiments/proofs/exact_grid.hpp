#pragma once
// The second checker of a polynomial or rational identity lhs = rhs, sharing no arithmetic with
// GiNaC's normal(): both sides are read as the expression trees the suite's algebra built (sums, products,
// integer powers, rational numbers, symbols; a function such as exp(λ) is an independent variable), each
// turned into a fraction n/d without cancelling anything, and the numerator N = n_l d_r − n_r d_l of the
// difference is evaluated exactly (integers) on the grid ∏_i {0, …, d_i}, d_i a structural bound on its degree
// in variable i (sums: max; products: sum; powers: n ×). A polynomial of degree ≤ d_i in each variable x_i
// that vanishes on such a grid is the zero polynomial (N. Alon, Combinatorial Nullstellensatz, Combin. Probab.
// Comput. 8 (1999), Lemma 2.1; induction on the variables, a nonzero univariate polynomial of degree ≤ d having
// at most d roots). So N vanishing on the grid proves lhs = rhs wherever both sides are defined, provided
// neither denominator is the zero polynomial, which the grid shows too.
// What it shares with GiNaC is the tree: GiNaC's constructors flatten sums and products, collect numeric
// coefficients of equal terms and combine equal factors (x·x⁻¹ = 1), but never expand a product or a power of a
// sum and never cancel a common factor that is not literally equal. The two sides are read separately, so nothing
// cancels between them before the grid evaluates N.
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
  std::uint64_t grid_points = 0;  ///< ∏ (d_i + 1)
  std::uint64_t evaluated = 0;    ///< points evaluated (all of them when zero)
  /// The first grid point where N ≠ 0, by variable, and N there (as text), when not zero.
  std::map<std::string, unsigned> witness;
  std::string witness_value;
};

/// Decides lhs = rhs (scalars, or matrices of the same shape entry by entry) on the grid. Throws
/// std::invalid_argument on an expression that is not rational in its variables (a non-integer power or a
/// non-rational number), on a grid of more than `max_points` points, and on a denominator that is the zero
/// polynomial.
GridVerdict grid_check(const GiNaC::ex& lhs, const GiNaC::ex& rhs, std::uint64_t max_points = 20'000'000);

/// The verdict as the lines of a <name>.grid.out file: the lemma, the bounds, the grid and the result.
std::string to_text(const GridVerdict& verdict);

}  // namespace affinterp::proofs
