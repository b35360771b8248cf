#pragma once
// The parts of the proofs of thesis §2.3's claims that several claims share, built from theory/origin's own
// energies and the printed formulas: the stationarity of the printed minimiser, and E2(o, o)'s Hessian.
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/identity.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace affinterp::claims::section_2_3 {

/// The printed minimiser v1x = …, …, v4y = … (rational functions of x, y), for a substitution step.
GiNaC::exmap printed_minimiser();

/// For each unknown u = v1x, …, v4y: ∂E2(o, o)/∂u equals its expanded form, and that form at the printed minimiser is
/// 0, a rational identity in x, y
/// (E2 from theory/origin's definitions, Def. 2.3.2).
std::vector<proofs::Identity> stationarity_identities();

/// The Hessian of E2(o, o) in the unknowns, in the order x-coordinates v1x … v4x, then y-coordinates: E2 is
/// quadratic in them, so its entries are polynomials in the origin's x, y.
GiNaC::matrix hessian_by_coordinate();

/// The Hessian splits: the x-coordinates' block equals the y-coordinates' block, and the blocks between them
/// vanish (so the Hessian is positive definite iff the x block is).
proofs::Identity hessian_blocks_identity();

/// ∃ x, y: some leading principal minor of H_x (Sylvester's criterion) is ≤ 0. Empty: E2(o, o) is strictly
/// convex in v for every origin.
proofs::Sentence hessian_sentence();

/// ∃ x, y: x² + 2xy + y² − 2x − 2y + 3 ≤ 0, the printed denominator. Empty: the printed formulas are defined
/// everywhere.
proofs::Sentence denominator_sentence();

}  // namespace affinterp::claims::section_2_3
