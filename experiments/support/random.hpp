#pragma once
// A seeded random source whose draws are the same on every platform (the standard distributions are
// implementation-defined; these conversions are not).
#include <cstdint>
#include <random>

namespace affinterp {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi), from the top 53 bits of one draw.
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }
  /// Uniform integer in [lo, hi] (inclusive), by rejection.
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
    if (span == 0) return static_cast<std::int64_t>(engine_());
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    std::uint64_t draw;
    do draw = engine_();
    while (draw >= limit);
    return lo + static_cast<std::int64_t>(draw % span);
  }
  std::uint64_t bits() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace affinterp
