#pragma once
// The sweep that tests an "iff" theorem: over a grid of parameter cases, a printed condition against an
// independent decision of the property, tallied in parallel (deterministically: chunks merge in order).
// Disagreements are counted both ways, and the simplest case of each kind (least `cost`) is kept as the
// seed of a counterexample.
#include "experiments/support/parallel.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace affinterp::claims::local {

template <class Case>
struct Disagreement {
  std::uint64_t count = 0;
  std::optional<Case> simplest;
  double simplest_cost = 0;

  void add(const Case& c, double cost) {
    ++count;
    if (!simplest || cost < simplest_cost) simplest = c, simplest_cost = cost;
  }
  void merge(const Disagreement& other) {
    count += other.count;
    if (other.simplest && (!simplest || other.simplest_cost < simplest_cost))
      simplest = other.simplest, simplest_cost = other.simplest_cost;
  }
};

template <class Case>
struct ConditionTally {
  std::uint64_t cases = 0;
  std::uint64_t property_holds = 0;
  Disagreement<Case> condition_only;  ///< the condition holds, the property does not
  Disagreement<Case> property_only;   ///< the property holds, the condition does not

  std::uint64_t disagreements() const { return condition_only.count + property_only.count; }
  nlohmann::json summary() const {
    return {{"cases", cases},
            {"property_holds", property_holds},
            {"agreements", cases - disagreements()},
            {"condition_true_property_false", condition_only.count},
            {"condition_false_property_true", property_only.count}};
  }
};

/// Tallies condition(c) against property(c) for every case, on `threads` threads.
template <class Case, class Condition, class Property, class Cost>
ConditionTally<Case> compare_over(const std::vector<Case>& cases, unsigned threads, Condition condition,
                                  Property property, Cost cost) {
  const auto chunks = parallel_chunks(cases.size(), threads, 256, [&](std::size_t begin, std::size_t end) {
    ConditionTally<Case> tally;
    for (std::size_t i = begin; i < end; ++i) {
      const Case& c = cases[i];
      const bool stated = condition(c), holds = property(c);
      ++tally.cases;
      tally.property_holds += holds;
      if (stated && !holds) tally.condition_only.add(c, cost(c));
      if (!stated && holds) tally.property_only.add(c, cost(c));
    }
    return tally;
  });
  ConditionTally<Case> total;
  for (const auto& chunk : chunks) {
    total.cases += chunk.cases;
    total.property_holds += chunk.property_holds;
    total.condition_only.merge(chunk.condition_only);
    total.property_only.merge(chunk.property_only);
  }
  return total;
}

}  // namespace affinterp::claims::local
