#pragma once
// The settings a check runs under: seed, size, threads, and where figures and benchmark data live.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::claims {

enum class Size {
  quick,  ///< reduced sweeps, for CI and the pinned-verdict tests
  full,   ///< the sizes the report states, for the main job
};

struct RunContext {
  std::uint64_t seed = 2012;
  Size size = Size::full;
  unsigned threads = 1;
  /// Where checks draw their figures; empty means draw none.
  std::filesystem::path figure_dir;
  /// Where Google Benchmark JSON outputs are read from, for measured claims; empty means none.
  std::filesystem::path bench_dir;

  /// `quick` under Size::quick, `full` under Size::full.
  template <class T>
  T pick(T quick, T full) const {
    return size == Size::quick ? quick : full;
  }
  /// A seed for one claim's sample, derived from the run's seed and the claim's ID, so that adding
  /// or reordering claims never changes another claim's sample.
  std::uint64_t seed_for(std::string_view claim_id) const;
  bool draws_figures() const { return !figure_dir.empty(); }
  /// The file stem a figure is drawn to (extensions are added by the plotter).
  std::filesystem::path figure_stem(std::string_view name) const { return figure_dir / name; }
  /// How the report refers to a drawn figure file, e.g. "figures/kaji-fig1.png".
  static std::string figure_ref(std::string_view file_name) { return "figures/" + std::string(file_name); }
  /// figure_ref of each file drawn into figure_dir.
  static std::vector<std::string> figure_refs(const std::vector<std::string>& file_names);
};

std::string_view to_string(Size size);

}  // namespace affinterp::claims
