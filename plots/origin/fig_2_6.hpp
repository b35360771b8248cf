#pragma once
// Thesis Fig. 2.6: the origins o = (x, y) at which min E1 = min E2(o, o), computed, beside the printed conic.
#include "theory/origin/two_triangles.hpp"

#include <ginac/ginac.h>

#include <filesystem>
#include <string>
#include <vector>

namespace affinterp::plots {

/// Draws the zero sets of the computed locus polynomial and the printed conic (both in x, y) over the
/// source triangles into the folder `dir`; returns the names of the files drawn.
std::vector<std::string> draw_fig_2_6(const std::filesystem::path& dir, const origin::TwoTriangles& config,
                                      const GiNaC::ex& computed_locus, const GiNaC::ex& printed_conic);

}  // namespace affinterp::plots
