#include "experiments/claims/registry.hpp"

#include "experiments/claims/catalogue.hpp"

#include <stdexcept>

namespace affinterp::claims {

void CheckRegistry::add(std::string_view claim_id, Check check) {
  if (find_claim(claim_id) == nullptr)
    throw std::logic_error("check registered for an uncatalogued claim: " + std::string(claim_id));
  if (!checks_.emplace(std::string(claim_id), std::move(check)).second)
    throw std::logic_error("claim has two checks: " + std::string(claim_id));
}

const Check* CheckRegistry::find(std::string_view claim_id) const {
  const auto it = checks_.find(claim_id);
  return it == checks_.end() ? nullptr : &it->second;
}

CheckRegistry build_registry() {
  CheckRegistry registry;
  register_local_checks(registry);
  register_global_checks(registry);
  register_origin_checks(registry);
  register_sym3_checks(registry);
  return registry;
}

}  // namespace affinterp::claims
