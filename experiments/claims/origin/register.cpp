#include "experiments/claims/origin/origin_checks.hpp"
#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_origin_checks(CheckRegistry& registry) {
  registry.add("thesis.sec-2.3.matrices", check_matrices);
  registry.add("thesis.sec-2.3.minimiser", check_minimiser);
  registry.add("thesis.sec-2.3.min-energy", check_min_energy);
  registry.add("thesis.sec-2.3.conic", check_conic);
}

}  // namespace affinterp::claims
