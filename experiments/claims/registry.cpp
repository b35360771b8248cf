#include "experiments/claims/registry.hpp"

#include <algorithm>
#include <cctype>
#include <regex>
#include <stdexcept>
#include <string>

namespace affinterp::claims {

namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// a < b with each maximal run of digits compared as a number.
bool id_less(std::string_view a, std::string_view b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      const std::size_t a_end = std::find_if_not(a.begin() + i, a.end(), is_digit) - a.begin();
      const std::size_t b_end = std::find_if_not(b.begin() + j, b.end(), is_digit) - b.begin();
      const std::string_view x = a.substr(i, a_end - i), y = b.substr(j, b_end - j);
      if (x.size() != y.size()) return x.size() < y.size();  // IDs write numbers without leading zeros
      if (x != y) return x < y;
      i = a_end, j = b_end;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

/// The registry the claim files fill, constructed on first use (before the first declaration is added).
ClaimRegistry& declared_claims() {
  static ClaimRegistry registry;
  return registry;
}

}  // namespace

bool run_order(const Claim& a, const Claim& b) {
  if (a.chapter != b.chapter) return a.chapter < b.chapter;
  return id_less(a.id, b.id);
}

void ClaimRegistry::add(Claim claim) {
  static const std::regex form(R"((kaji|thesis|atlas|atlas3|sequel)\.[A-Za-z0-9.-]+)");
  const std::string id(claim.id);
  if (!std::regex_match(id, form)) throw std::logic_error("malformed claim ID: '" + id + "'");
  if (find(claim.id) != nullptr) throw std::logic_error("claim declared twice: " + id);
  if (claim.where.empty() || claim.statement.empty())
    throw std::logic_error("claim " + id + " does not say where it is printed and what it states");
  claims_.insert(std::upper_bound(claims_.begin(), claims_.end(), claim, run_order), std::move(claim));
}

const Claim* ClaimRegistry::find(std::string_view claim_id) const {
  const auto it = std::find_if(claims_.begin(), claims_.end(), [&](const Claim& c) { return c.id == claim_id; });
  return it == claims_.end() ? nullptr : &*it;
}

const ClaimRegistry& registered_claims() { return declared_claims(); }

ClaimDeclaration::ClaimDeclaration(Claim claim) { declared_claims().add(std::move(claim)); }

}  // namespace affinterp::claims
