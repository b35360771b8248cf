#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_local_checks(CheckRegistry& /*registry*/) {}

}  // namespace affinterp::claims
