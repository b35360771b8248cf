#pragma once
// The steps of an identity kept in its expression tree, not performed while it is built: the derivative d/dx e,
// the substitution e|_{x=v}, the determinant, the transpose and the product of matrices, and one entry of a
// matrix. Each is a GiNaC function with no evaluation of its own (it stays symbolic) that prints as ginsh's own
// command, so that ginsh performs the step when it reads the script:
//   derivative(e, x)      diff(e,x)
//   substitution(e, x, v) subs(e,{x},{v})
//   determinant_of(M)     determinant(M)
//   transposed(M)         transpose(M)
//   product(A, B)         evalm(A*B)
//   entry(M, k)           op(M,k)          (the k-th entry of M, row by row, from 0)
// A matrix is written [[a,b],[c,d]], as ginsh reads it. The identity prover's GiNaC checker performs the steps
// with GiNaC's diff, subs, evalm and determinant (perform_steps); the exact-grid checker performs them with its
// own arithmetic (exact_grid.hpp). read_script_expression reads the text back into the same nodes.
#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace affinterp::proofs {

/// d/dx e, n times.
GiNaC::ex derivative(const GiNaC::ex& e, const GiNaC::symbol& x, unsigned n = 1);
/// e with v for x.
GiNaC::ex substitution(const GiNaC::ex& e, const GiNaC::symbol& x, const GiNaC::ex& v);
/// e with each symbol of `values` replaced, one substitution node per symbol, in the order of their names (the
/// map's own order follows GiNaC's hash values, which change from run to run; the values must not contain the
/// symbols replaced, so that any order gives the same value).
GiNaC::ex substitution(const GiNaC::ex& e, const GiNaC::exmap& values);
GiNaC::ex determinant_of(const GiNaC::ex& M);
GiNaC::ex transposed(const GiNaC::ex& M);
/// A·B, and A·B·C… left to right.
GiNaC::ex product(const GiNaC::ex& A, const GiNaC::ex& B);
GiNaC::ex product(const std::vector<GiNaC::ex>& factors);
/// The k-th entry of M, row by row from 0.
GiNaC::ex entry(const GiNaC::ex& M, unsigned k);

/// The step nodes, as the checkers recognise them.
enum class Step { none, derivative, substitution, determinant, transpose, product, entry };
Step step_of(const GiNaC::ex& e);

/// Rows and columns of a matrix-valued expression (a GiNaC matrix, a transpose or a product of them); {0, 0}
/// for a scalar.
std::pair<unsigned, unsigned> shape(const GiNaC::ex& e);

/// `e` with every step performed by GiNaC (diff, subs, evalm, determinant, transpose), innermost first: what the
/// GiNaC checker decides. `e` itself is left as it is.
GiNaC::ex perform_steps(const GiNaC::ex& e);

/// Whether `e` holds a step node anywhere.
bool has_steps(const GiNaC::ex& e);

/// One side of a script line, in the syntax the nodes print, read back into the same tree; the symbols from
/// `symbols`, any other name an error.
GiNaC::ex read_script_expression(const std::string& text, const GiNaC::symtab& symbols);

}  // namespace affinterp::proofs
