#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_sym3_checks(CheckRegistry& /*registry*/) {}

}  // namespace affinterp::claims
