#pragma once
// GiNaC polynomials as theory/logic's polynomials: the atoms of the sentences that QEPCAD B and Z3 decide are built
// from the suite's own symbolic algebra (theory/origin, or theory/global and theory/sym3 over GiNaC::ex).
#include "theory/logic/polynomial.hpp"

#include <ginac/ginac.h>

#include <string>

namespace affinterp::proofs {

/// `e` as a polynomial with rational coefficients in its symbols (by name), expanded by theory/logic's own
/// arithmetic. Throws std::invalid_argument when `e` is not one (a negative or non-integer power, a function, a
/// non-rational number).
logic::Polynomial to_polynomial(const GiNaC::ex& e);

/// The printed text of `e`, as scripts, transcripts and error messages show it: GiNaC's default syntax (which ginsh
/// and GiNaC's parser read) with every sum's terms and every product's factors sorted by their text and every sum
/// inside a product or an integer power given one sign, so that the same expression reads the same in every run
/// (GiNaC's own order and signs follow hash values that move from run to run).
std::string text_of(const GiNaC::ex& e);

}  // namespace affinterp::proofs
