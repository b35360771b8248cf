#pragma once
// The checks of the local claims (Kaji §3 and Appendix; thesis §2.2), one function per claim.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

namespace affinterp::claims::local {

Outcome check_eq1_affine_map(const RunContext& ctx);           // kaji.eq1.affine-map
Outcome check_linear_collapse(const RunContext& ctx);          // kaji.linear.collapse
Outcome check_polar_det(const RunContext& ctx);                // kaji.polar.det
Outcome check_polar_degenerate(const RunContext& ctx);         // kaji.polar.degenerate
Outcome check_svd_degenerate(const RunContext& ctx);           // kaji.svd.degenerate
Outcome check_exp_endpoints(const RunContext& ctx);            // kaji.exp.endpoints
Outcome check_exp_det_positive(const RunContext& ctx);         // kaji.exp.det-positive
Outcome check_exp_det_monotone(const RunContext& ctx);         // kaji.exp.det-monotone
Outcome check_appendix_polar_from_svd(const RunContext& ctx);  // kaji.appendix.polar-from-svd
Outcome check_thm_2_2_1(const RunContext& ctx);                // thesis.thm-2.2.1
Outcome check_thm_2_2_2(const RunContext& ctx);                // thesis.thm-2.2.2
Outcome check_thm_2_2_3(const RunContext& ctx);                // thesis.thm-2.2.3
Outcome check_thm_2_2_4(const RunContext& ctx);                // thesis.thm-2.2.4
Outcome check_thm_2_2_5(const RunContext& ctx);                // thesis.thm-2.2.5
Outcome check_thm_2_2_6(const RunContext& ctx);                // thesis.thm-2.2.6
Outcome check_example_2_2_4(const RunContext& ctx);            // thesis.ex-2.2.4

}  // namespace affinterp::claims::local
