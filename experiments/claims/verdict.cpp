#include "experiments/claims/verdict.hpp"

#include <array>
#include <utility>

namespace affinterp::claims {

namespace {
constexpr std::array<std::pair<Verdict, std::string_view>, 7> names{{
    {Verdict::pending, "pending"},
    {Verdict::confirmed, "confirmed"},
    {Verdict::refuted, "refuted"},
    {Verdict::corrected, "corrected"},
    {Verdict::reproduced, "reproduced"},
    {Verdict::not_reproduced, "not-reproduced"},
    {Verdict::inconclusive, "inconclusive"},
}};
}  // namespace

std::string_view to_string(Verdict v) {
  for (const auto& [verdict, name] : names)
    if (verdict == v) return name;
  return "?";
}

std::optional<Verdict> parse_verdict(std::string_view text) {
  for (const auto& [verdict, name] : names)
    if (name == text) return verdict;
  return std::nullopt;
}

}  // namespace affinterp::claims
