#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

void register_origin_checks(CheckRegistry& /*registry*/) {}

}  // namespace affinterp::claims
