#include "experiments/claims/verdict.hpp"

#include <array>
#include <utility>

namespace affinterp::claims {

namespace {
constexpr std::array<std::pair<Verdict, std::string_view>, 8> names{{
    {Verdict::pending, "pending"},
    {Verdict::confirmed, "confirmed"},
    {Verdict::refuted, "refuted"},
    {Verdict::corrected, "corrected"},
    {Verdict::reproduced, "reproduced"},
    {Verdict::not_reproduced, "not-reproduced"},
    {Verdict::inconclusive, "inconclusive"},
    {Verdict::machine_dependent, "machine-dependent"},
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

namespace {
constexpr std::array<std::pair<Strength, std::string_view>, 10> strength_names{{
    {Strength::unstated, "unstated"},
    {Strength::proved_kernel_checked, "proved-kernel-checked"},
    {Strength::proved, "proved"},
    {Strength::proved_hand_steps, "proved-with-hand-steps"},
    {Strength::proved_one_decider, "proved-one-decider"},
    {Strength::proved_citing, "proved-citing"},
    {Strength::exact_counterexample, "exact-counterexample"},
    {Strength::grid, "grid"},
    {Strength::sample, "sample"},
    {Strength::measured, "measured"},
}};
}  // namespace

std::string_view to_string(Strength s) {
  for (const auto& [strength, name] : strength_names)
    if (strength == s) return name;
  return "?";
}

std::optional<Strength> parse_strength(std::string_view text) {
  for (const auto& [strength, name] : strength_names)
    if (name == text) return strength;
  return std::nullopt;
}

}  // namespace affinterp::claims
