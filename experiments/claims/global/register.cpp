#include "experiments/claims/global/global_checks.hpp"

namespace affinterp::claims {

void register_global_checks(CheckRegistry& registry) {
  register_similarity_error_checks(registry);
  register_quadratic_form_checks(registry);
  register_acol_constraint_check(registry);
  register_figure_checks(registry);
  register_symmetrization_check(registry);
}

}  // namespace affinterp::claims
