#pragma once
// The deciders of first-order sentences over the reals: QEPCAD B (cylindrical algebraic decomposition) on
// <sentence>.qepcad, Z3 (nlsat) and cvc5 (cylindrical algebraic coverings) on <sentence>.smt2, each run as a
// limited child process. A run's
// transcript is what the proofs store (transcript.hpp); checks read answers from stored transcripts and only
// `affinterp prove` and `affinterp decide` call run_decider.
#include "experiments/proofs/decider_output.hpp"
#include "experiments/proofs/transcript.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::proofs {

struct DeciderLimits {
  /// Each decider's limit in CPU seconds, so that whether a sentence is decided does not depend on the load.
  double seconds = 60;
  /// The wall-clock limit, as a multiple of `seconds`: a backstop for proofs; `decide` uses 1, so that its
  /// answer comes within the time it states.
  double wall_factor = 4;
  std::size_t address_space_bytes = std::size_t{1536} << 20;  ///< RLIMIT_AS of each decider
  long qepcad_cells = 100'000'000;                            ///< QEPCAD's +N (garbage-collected space)
  long z3_megabytes = 1024;                                   ///< z3 -memory:
  /// A formulation tried for the record (Proof::attempts), not part of a proof: `affinterp prove`
  /// decides it when its transcript is missing or stale, but `--all` does not re-decide it.
  bool attempt = false;
};

struct Decider {
  std::string_view tool;             ///< "qepcad", "z3", "cvc5"
  std::string_view input_extension;  ///< ".qepcad", ".smt2"
  std::string_view debian_package;   ///< where its version is read from
};

/// QEPCAD B, Z3, cvc5: the order of SentenceDecision::runs.
const std::vector<Decider>& sentence_deciders();

/// The installed Debian package's version of `decider` ("" when it is not installed), read once per process.
std::string installed_version(const Decider& decider);

/// Runs `decider` on `input_file` under `limits` and returns its transcript (timings removed from the output;
/// a last line when the limit stopped it). Writes nothing.
Transcript run_decider(const Decider& decider, const std::filesystem::path& input_file, const std::string& input_text,
                       const DeciderLimits& limits);

/// The answer a transcript gives; `input_text` names QEPCAD's witness coordinates (its variable list).
DeciderAnswer answer_of(const Transcript& transcript, const std::string& input_text);

}  // namespace affinterp::proofs
