#pragma once
// Which check decides which claim. Each body of theory registers its checks in one function, called
// from build_registry(); a catalogued claim without a check is reported as `pending`.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace affinterp::claims {

using Check = std::function<Outcome(const RunContext&)>;

class CheckRegistry {
 public:
  /// Registers the check of a catalogued claim; throws std::logic_error for an unknown or
  /// already-registered ID.
  void add(std::string_view claim_id, Check check);
  const Check* find(std::string_view claim_id) const;
  std::size_t size() const { return checks_.size(); }

 private:
  std::map<std::string, Check, std::less<>> checks_;
};

// One registration function per body of theory (experiments/claims/<part>/register.cpp).
void register_local_checks(CheckRegistry& registry);
void register_global_checks(CheckRegistry& registry);
void register_origin_checks(CheckRegistry& registry);
void register_sym3_checks(CheckRegistry& registry);

/// Every check the suite has.
CheckRegistry build_registry();

}  // namespace affinterp::claims
