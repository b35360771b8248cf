#include "experiments/claims/registry.hpp"
#include "experiments/claims/sym3/accuracy.hpp"
#include "experiments/claims/sym3/algebra.hpp"
#include "experiments/claims/sym3/speed.hpp"

namespace affinterp::claims {

void register_sym3_checks(CheckRegistry& registry) {
  registry.add("thesis.eq-3.charpoly", sym3::check_charpoly);
  registry.add("thesis.viete", sym3::check_viete);
  registry.add("thesis.sd.case1", sym3::check_sd_case1);
  registry.add("thesis.sd.case2", sym3::check_sd_case2);
  registry.add("thesis.sd.case3", sym3::check_sd_case3);
  registry.add("thesis.exp.accuracy", sym3::check_exp_accuracy);
  registry.add("thesis.eig.speedup", sym3::check_eig_speedup);
  registry.add("thesis.exp.speedup", sym3::check_exp_speedup);
  registry.add("thesis.app.speedup", sym3::check_app_speedup);
}

}  // namespace affinterp::claims
