#pragma once
// The claims the suite decides. Every claim file registers its claim (claim.hpp) into one registry, read
// by registered_claims(); there is no list to update. The registry keeps its claims in run order, whatever
// order the program's static initialisation added them in.
#include "experiments/claims/claim.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace affinterp::claims {

class ClaimRegistry {
 public:
  /// Adds a claim; throws std::logic_error for an ID not of the form kaji.*, thesis.*, atlas.*, atlas3.* or sequel.*
  /// (letters, digits, '.', '-'), an ID already added, or an empty `where` or `statement`.
  void add(Claim claim);
  /// The claims in run order (run_order).
  std::span<const Claim> claims() const { return claims_; }
  const Claim* find(std::string_view claim_id) const;

 private:
  std::vector<Claim> claims_;
};

/// Every claim declared in the program (a ClaimDeclaration per claim file).
const ClaimRegistry& registered_claims();

/// The run and report order: by chapter (local, global, origin, sym3), then by ID, comparing runs of
/// digits as numbers ("thesis.thm-2.2.9" before "thesis.thm-2.2.10").
bool run_order(const Claim& a, const Claim& b);

}  // namespace affinterp::claims
