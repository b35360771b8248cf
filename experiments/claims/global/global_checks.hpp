#pragma once
// The global interpolation checks (Kaji §4, Appendix), one registration function per file.
#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_similarity_error_checks(CheckRegistry& registry);  // similarity_error_claims.cpp
void register_quadratic_form_checks(CheckRegistry& registry);    // quadratic_form_claims.cpp
void register_acol_constraint_check(CheckRegistry& registry);    // acol_constraint.cpp
void register_symmetrization_check(CheckRegistry& registry);     // symmetrization.cpp
void register_figure_checks(CheckRegistry& registry);            // figure_claims.cpp

}  // namespace affinterp::claims
