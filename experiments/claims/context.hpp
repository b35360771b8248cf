#pragma once
// The settings a check runs under: the run's size, threads and folders, and the claim's own seed.
#include "experiments/proofs/decide_sentence.hpp"

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

/// What every check of a run shares: sweep size, threads, and where figures and benchmark data live.
struct RunSettings {
  Size size = Size::full;
  unsigned threads = 1;
  /// Where checks draw their figures; empty means draw none.
  std::filesystem::path figure_dir;
  /// Where Google Benchmark JSON outputs are read from, for measured claims; empty means none.
  std::filesystem::path bench_dir;
  /// Where checks write the sentence files of their proofs, proof_dir/<claim id>/<name>.<ext> beside the
  /// deciders' transcripts; empty means a temporary folder per sentence, kept nowhere.
  std::filesystem::path proof_dir;
  /// The stored transcripts the proofs read their answers from, answer_dir/<claim id>/<name>.<tool>.out
  /// (proofs as data: a check never starts a decider); this checkout's reports/proofs by default.
  std::filesystem::path answer_dir = committed_answers();
  /// When set, every decider run the proofs need is recorded here (`affinterp prove`).
  proofs::ProofPlan* plan = nullptr;

  /// This checkout's reports/proofs, where the committed transcripts are.
  static std::filesystem::path committed_answers();

  /// `quick` under Size::quick, `full` under Size::full.
  template <class T>
  T pick(T quick, T full) const {
    return size == Size::quick ? quick : full;
  }
  bool draws_figures() const { return !figure_dir.empty(); }
  /// The file stem a figure is drawn to (extensions are added by the plotter).
  std::filesystem::path figure_stem(std::string_view name) const { return figure_dir / name; }
  /// How the report refers to a drawn figure file, e.g. "figures/kaji-fig1.png".
  static std::string figure_ref(std::string_view file_name) { return "figures/" + std::string(file_name); }
  /// figure_ref of each file drawn into figure_dir.
  static std::vector<std::string> figure_refs(const std::vector<std::string>& file_names);
};

/// What one check runs under, as the engine hands it over: the run's settings, the claim's ID and the
/// claim's own seed. A check draws every random sample from `seed` and never names its own ID.
struct ClaimContext : RunSettings {
  std::string_view claim_id;
  std::uint64_t seed = 0;  ///< RunContext::seed_for(claim_id)

  /// Where this claim's proof sentences go: proof_dir/<claim id>, named "proofs/<claim id>" in claims.json
  /// (relative to the report's folder, like figures).
  proofs::SentenceFiles proof_files() const;
};

/// A run: the settings and the run's seed, from which each claim's seed is derived.
struct RunContext : RunSettings {
  std::uint64_t seed = 2012;

  /// A seed for one claim's sample, derived from the run's seed and the claim's ID, so that adding
  /// or reordering claims never changes another claim's sample.
  std::uint64_t seed_for(std::string_view claim_id) const;
  /// The context the check of `claim_id` runs under.
  ClaimContext for_claim(std::string_view claim_id) const { return {{*this}, claim_id, seed_for(claim_id)}; }
};

std::string_view to_string(Size size);

}  // namespace affinterp::claims
