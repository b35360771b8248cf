#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_global_checks(CheckRegistry& /*registry*/) {}

}  // namespace affinterp::claims
