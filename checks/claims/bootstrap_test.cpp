// The percentile bootstrap of experiments/bench/bootstrap.hpp: the same interval for a seed, intervals that
// cover a known median about 95% of the time with the width the normal theory predicts, and the placement
// of an interval against a band.
#include "experiments/bench/bootstrap.hpp"

#include "experiments/support/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace affinterp::bench::bootstrap_test {
namespace {

/// n draws from the normal distribution N(mu, sigma²) (Box–Muller).
std::vector<double> normal_sample(Rng& rng, std::size_t n, double mu, double sigma) {
  std::vector<double> x(n);
  for (double& v : x) {
    const double u1 = 1 - rng.uniform(0, 1), u2 = rng.uniform(0, 1);
    v = mu + sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
  }
  return x;
}

TEST(Bootstrap, Median) {
  EXPECT_EQ(median(std::vector<double>{3, 1, 2}), 2);
  EXPECT_EQ(median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_THROW(median(std::vector<double>{}), std::invalid_argument);
}

TEST(Bootstrap, IsDeterministicForASeed) {
  const std::vector<double> slow = {10, 11, 12, 10.5, 11.5, 13, 10.2, 11.1, 12.4, 10.9};
  const std::vector<double> fast = {5, 5.5, 5.2, 5.1, 6, 5.3, 5.05, 5.4, 5.6, 5.25};
  const Interval a = ratio_of_medians_ci95({slow}, {fast}, 42), b = ratio_of_medians_ci95({slow}, {fast}, 42);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  const Interval c = ratio_of_medians_ci95({slow}, {fast}, 43);
  EXPECT_TRUE(a.lo != c.lo || a.hi != c.hi);  // another seed, another resampling
  const double ratio = median(slow) / median(fast);
  EXPECT_LT(a.lo, ratio);
  EXPECT_GT(a.hi, ratio);
}

TEST(Bootstrap, ConstantSamplesGiveAPointInterval) {
  const Interval ci = ratio_of_medians_ci95({std::vector<double>(10, 6.0)}, {std::vector<double>(12, 2.0)}, 1);
  EXPECT_EQ(ci.lo, 3.0);
  EXPECT_EQ(ci.hi, 3.0);
}

TEST(Bootstrap, CoversAKnownMedianAbout95PercentOfTheTime) {
  // 400 samples of 60 draws from N(5, 1): the 95% interval of the median should contain 5 in about 95% of
  // them (the percentile bootstrap of a median is slightly conservative or liberal at small n; a binomial
  // 400 × 0.95 has standard deviation 4.4, so 88%–99% is a wide margin), and its mean width should be near
  // the normal theory's 2 · 1.96 · σ √(π/2) / √n = 0.634.
  Rng rng(2015);
  int covered = 0;
  double width = 0;
  constexpr int trials = 400;
  for (int t = 0; t < trials; ++t) {
    const Interval ci = bootstrap_interval(
        {{normal_sample(rng, 60, 5, 1)}}, [](const auto& s) { return median(s[0]); }, rng.bits(), 0.95, 1000);
    covered += ci.lo <= 5 && 5 <= ci.hi;
    width += (ci.hi - ci.lo) / trials;
  }
  EXPECT_GE(covered, static_cast<int>(0.88 * trials));
  EXPECT_LE(covered, static_cast<int>(0.99 * trials));
  EXPECT_NEAR(width, 2 * 1.96 * std::sqrt(std::numbers::pi / 2) / std::sqrt(60.0), 0.15);
}

TEST(Bootstrap, RatioIntervalCoversAKnownRatio) {
  // Timings N(300, 15²) and N(100, 5²): the ratio of medians is 3.
  Rng rng(7);
  int covered = 0;
  constexpr int trials = 200;
  for (int t = 0; t < trials; ++t) {
    const Interval ci = bootstrap_interval(
        {{normal_sample(rng, 20, 300, 15)}, {normal_sample(rng, 20, 100, 5)}},
        [](const auto& s) { return median(s[0]) / median(s[1]); }, rng.bits(), 0.95, 1000);
    covered += ci.lo <= 3 && 3 <= ci.hi;
  }
  EXPECT_GE(covered, static_cast<int>(0.85 * trials));
}

TEST(Bootstrap, ProcessesThatDisagreeWidenTheInterval) {
  // Ten repetitions in each of two processes, tight within each, the second process 20% slower on `slow` only
  // (a slow phase of the machine): pooled as one process the interval is narrow; kept as two, the first stage
  // draws either process alone part of the time, and the interval spans both processes' ratios.
  std::vector<double> slow_a(10), slow_b(10), fast_a(10), fast_b(10);
  for (int i = 0; i < 10; ++i) {
    slow_a[i] = 300 + i * 0.1, slow_b[i] = 360 + i * 0.1;
    fast_a[i] = 100 + i * 0.05, fast_b[i] = 100 + i * 0.05;
  }
  std::vector<double> slow_all = slow_a, fast_all = fast_a;
  slow_all.insert(slow_all.end(), slow_b.begin(), slow_b.end());
  fast_all.insert(fast_all.end(), fast_b.begin(), fast_b.end());
  const Interval one = ratio_of_medians_ci95({slow_all}, {fast_all}, 5);
  const Interval two = ratio_of_medians_ci95({slow_a, slow_b}, {fast_a, fast_b}, 5);
  EXPECT_LT(two.lo, 3.01);
  EXPECT_GT(two.hi, 3.59);
  EXPECT_GT(two.hi - two.lo, one.hi - one.lo);
  EXPECT_THROW(ratio_of_medians_ci95({slow_a, slow_b}, {fast_a}, 5), std::invalid_argument);
}

/// Ten repetitions spread evenly over value · (1 ± spread).
std::vector<double> repetitions(double value, double spread) {
  std::vector<double> x(10);
  for (int i = 0; i < 10; ++i) x[i] = value * (1 + spread * (2.0 * i / 9 - 1));
  return x;
}

const Statistic kRatio = [](const auto& s) { return median(s[0]) / median(s[1]); };

/// One run of two processes timing `slow` and `fast` (ratio slow / fast), spread ±spread.
RunSamples run(double slow, double fast, double spread = 0.01) {
  return {{repetitions(slow, spread), repetitions(slow, spread)},
          {repetitions(fast, spread), repetitions(fast, spread)}};
}

TEST(HierarchicalBootstrap, OneRunIsTheRunsOwnIntervalDrawForDraw) {
  const RunSamples one = run(350, 100, 0.05);
  const Interval alone = bootstrap_interval(one, kRatio, 11), nested = hierarchical_interval({one}, kRatio, 11);
  EXPECT_EQ(alone.lo, nested.lo);
  EXPECT_EQ(alone.hi, nested.hi);
}

TEST(HierarchicalBootstrap, IsDeterministicForASeed) {
  const std::vector<RunSamples> runs = {run(350, 100), run(360, 100), run(340, 100, 0.05)};
  const Interval a = hierarchical_interval(runs, kRatio, 42), b = hierarchical_interval(runs, kRatio, 42);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  const Interval c = hierarchical_interval(runs, kRatio, 43);
  EXPECT_TRUE(a.lo != c.lo || a.hi != c.hi);  // another seed, another resampling
}

TEST(HierarchicalBootstrap, AWildRunWidensTheInterval) {
  // Five runs that agree on 3.5 (each tight), then the same five with a sixth at 5.0: were the runs pooled
  // as one sample, one run in six would barely move the median; drawn as runs, resamples with none, one or
  // several copies of it spread the statistic, and the interval widens towards 5.
  std::vector<RunSamples> runs = {run(350, 100), run(348, 100), run(352, 100), run(351, 100), run(349, 100)};
  const Interval steady = hierarchical_interval(runs, kRatio, 7);
  runs.push_back(run(500, 100));
  const Interval wild = hierarchical_interval(runs, kRatio, 7);
  EXPECT_LT(steady.hi - steady.lo, 0.05);
  EXPECT_GT(wild.hi - wild.lo, 3 * (steady.hi - steady.lo));
  EXPECT_GT(wild.hi, 3.6);
  // Pooling every repetition into one run and one process (no run level) gives a narrower interval.
  RunSamples flat(2, ByProcess(1));
  for (const RunSamples& r : runs)
    for (std::size_t s = 0; s < 2; ++s)
      for (const auto& process : r[s]) flat[s][0].insert(flat[s][0].end(), process.begin(), process.end());
  const Interval unnested = bootstrap_interval(flat, kRatio, 7);
  EXPECT_GT(wild.hi - wild.lo, unnested.hi - unnested.lo);
}

TEST(HierarchicalBootstrap, RunsOfOtherShapesAreRefused) {
  EXPECT_THROW(hierarchical_interval({}, kRatio, 1), std::invalid_argument);
  EXPECT_THROW(hierarchical_interval({run(350, 100), {run(350, 100)[0]}}, kRatio, 1), std::invalid_argument);
}

TEST(Bootstrap, PlacementAgainstABand) {
  const Interval band{2.0, 4.0};
  EXPECT_EQ(placement({2.5, 3.5}, band), Placement::inside);
  EXPECT_EQ(placement({2.0, 4.0}, band), Placement::inside);
  EXPECT_EQ(placement({4.1, 4.5}, band), Placement::outside);
  EXPECT_EQ(placement({1.0, 1.9}, band), Placement::outside);
  EXPECT_EQ(placement({3.5, 4.5}, band), Placement::straddles);
  EXPECT_EQ(placement({1.5, 2.5}, band), Placement::straddles);
  EXPECT_EQ(placement({1.0, 5.0}, band), Placement::straddles);
}

}  // namespace
}  // namespace affinterp::bench::bootstrap_test
