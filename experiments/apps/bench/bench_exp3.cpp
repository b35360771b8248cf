// bench_exp3: eigenvalues and exponentials of 3×3 symmetric matrices (thesis §3.4, Figs 3.1 and 3.2).
// Every registered algorithm runs over the same 4096 matrices of the thesis's distribution S = MᵀM
// (M uniform in [−1, 1]), cycled; the counter ns_per_matrix is the CPU time per matrix. Each benchmark
// is repeated (kRepetitions, each kept in the JSON file) and reports mean, median and spread; speed claims
// read the medians and bootstrap over the repetitions.
#include "experiments/apps/bench/bench_context.hpp"
#include "experiments/bench/speed_figures.hpp"
#include "experiments/inputs/sym3/families.hpp"
#include "theory/sym3/algorithms.hpp"

#include <string>
#include <vector>
#include <xsimd/xsimd.hpp>

namespace affinterp::bench {
namespace {

using sym3::Mat3;
using sym3::Vec3;

constexpr std::size_t kMatrices = 4096;
constexpr std::uint64_t kSeed = 2015;  // the thesis's year; any fixed seed does
constexpr double kMinSeconds = 0.2;

const std::vector<Mat3>& matrices() {
  static const std::vector<Mat3> S = sym3::thesis_distribution(kSeed, kMatrices);
  return S;
}

void finish(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kMatrices));
  state.counters["ns_per_matrix"] = ns_per_item(kMatrices);
}

void eigenvalues(benchmark::State& state, const sym3::EigAlgorithm* algorithm) {
  const auto& S = matrices();
  for (auto _ : state)
    for (const Mat3& s : S) {
      Vec3 lambda = algorithm->eigenvalues(s);
      benchmark::DoNotOptimize(lambda);
    }
  finish(state);
}

void exponential(benchmark::State& state, const sym3::ExpAlgorithm* algorithm) {
  const auto& S = matrices();
  for (auto _ : state)
    for (const Mat3& s : S) {
      Mat3 E = algorithm->exp(s);
      benchmark::DoNotOptimize(E);
    }
  finish(state);
}

void exponential_batched(benchmark::State& state) {
  const auto& S = matrices();
  std::vector<Mat3> E(S.size());
  for (auto _ : state) {
    sym3::exp_batched(S, E);
    benchmark::DoNotOptimize(E.data());
    benchmark::ClobberMemory();
  }
  finish(state);
}

/// The part of exp3/affinterp-batched that is xsimd's exponential: four exp of a batch per batch of matrices, as
/// theory/sym3/spectral_split.hpp's exp_shifted takes them (e^{λ_mid}, e^{λ_mid ± ρ}, e^{λ_far}), on arguments of
/// the eigenvalues' range (the matrices' diagonal entries and their mean), laid out as structure of arrays
/// beforehand. What the batched exponential takes beyond it is the split, the assembly and the layout.
void four_exponentials(benchmark::State& state) {
  using Batch = xsimd::batch<double>;
  constexpr std::size_t W = Batch::size;
  const auto& S = matrices();
  std::vector<double> lanes[4];
  for (const Mat3& s : S) {
    lanes[0].push_back(s(0, 0)), lanes[1].push_back(s(1, 1)), lanes[2].push_back(s(2, 2));
    lanes[3].push_back(s.trace() / 3);
  }
  for (auto _ : state)
    for (std::size_t i = 0; i + W <= S.size(); i += W) {
      Batch sum = xsimd::exp(Batch::load_unaligned(&lanes[0][i]));
      for (int k = 1; k < 4; ++k) sum += xsimd::exp(Batch::load_unaligned(&lanes[k][i]));
      benchmark::DoNotOptimize(sum);
    }
  finish(state);
}

void register_all() {
  auto configure = [](benchmark::internal::Benchmark* b) {
    b->Repetitions(kRepetitions)->DisplayAggregatesOnly(true)->MinTime(kMinSeconds);
  };
  for (const auto& algorithm : sym3::eig_algorithms())
    configure(benchmark::RegisterBenchmark(("eig3/" + std::string(algorithm.name)).c_str(), eigenvalues, &algorithm));
  for (const auto& algorithm : sym3::exp_algorithms())
    configure(benchmark::RegisterBenchmark(("exp3/" + std::string(algorithm.name)).c_str(), exponential, &algorithm));
  configure(benchmark::RegisterBenchmark(std::string(names::exp_ours_batched).c_str(), exponential_batched));
  configure(benchmark::RegisterBenchmark(std::string(names::exp_ours_batched_exponentials).c_str(), four_exponentials));
}

}  // namespace
}  // namespace affinterp::bench

int main(int argc, char** argv) {
  affinterp::bench::register_all();
  return affinterp::bench::run_benchmarks(argc, argv);
}
