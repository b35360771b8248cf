#include "experiments/claims/local/checks.hpp"
#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_local_checks(CheckRegistry& registry) {
  registry.add("kaji.eq1.affine-map", local::check_eq1_affine_map);
  registry.add("kaji.linear.collapse", local::check_linear_collapse);
  registry.add("kaji.polar.det", local::check_polar_det);
  registry.add("kaji.polar.degenerate", local::check_polar_degenerate);
  registry.add("kaji.svd.degenerate", local::check_svd_degenerate);
  registry.add("kaji.exp.endpoints", local::check_exp_endpoints);
  registry.add("kaji.exp.det-positive", local::check_exp_det_positive);
  registry.add("kaji.exp.det-monotone", local::check_exp_det_monotone);
  registry.add("kaji.appendix.polar-from-svd", local::check_appendix_polar_from_svd);
  registry.add("thesis.thm-2.2.1", local::check_thm_2_2_1);
  registry.add("thesis.thm-2.2.2", local::check_thm_2_2_2);
  registry.add("thesis.thm-2.2.3", local::check_thm_2_2_3);
  registry.add("thesis.thm-2.2.4", local::check_thm_2_2_4);
  registry.add("thesis.thm-2.2.5", local::check_thm_2_2_5);
  registry.add("thesis.thm-2.2.6", local::check_thm_2_2_6);
  registry.add("thesis.ex-2.2.4", local::check_example_2_2_4);
}

}  // namespace affinterp::claims
