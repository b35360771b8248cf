#pragma once
// Thesis Fig. 2.6: the origins o = (x, y) at which min E1 = min E2(o, o), computed, beside the printed conic.
#include "experiments/claims/context.hpp"
#include "theory/origin/two_triangles.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace affinterp::figures {

/// Draws the zero sets of the computed locus polynomial and the printed conic (both in x, y) over the
/// source triangles; returns the report's references to the files drawn.
std::vector<std::string> draw_fig_2_6(const claims::RunContext& ctx, const origin::TwoTriangles& config,
                                      const GiNaC::ex& computed_locus, const GiNaC::ex& printed_conic);

}  // namespace affinterp::figures
