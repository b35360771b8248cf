#pragma once
// Proofs as data: a decider's answer to a sentence is its transcript, stored beside the sentence
// file as <sentence>.<tool>.out. A few header lines key it to the input it answered (the SHA-256 of the input
// file's text, the decider and its version); below them stands what the decider printed, timings removed.
// A check reads the answer from the transcript and never starts a decider; `affinterp prove` writes them.
//
//   # affinterp transcript
//   # decider: z3 4.8.12-3.1
//   # input: cond-not-prop.E.smt2 sha256:5d41402abc4b2a76b9719d911017c592…
//   # cpu-limit-seconds: 60
//   # seconds: 0.21
//   # cpu-seconds: 0.18
//   # max-rss-kb: 31756
//   unsat
// (the last two lines are absent in transcripts written before they were recorded).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace affinterp::proofs {

struct Transcript {
  std::string tool;          ///< "qepcad", "z3", "cvc5"
  std::string version;       ///< the Debian package's version that answered, e.g. "4.8.12-3.1"
  std::string input;         ///< the input file's name, e.g. "cond-not-prop.E.smt2"
  std::string input_sha256;  ///< of the input file's text, lower-case hex
  double cpu_limit_seconds = 0;
  double seconds = 0;                   ///< wall time the decider took
  std::string output;                   ///< what the decider printed, timings removed
  std::optional<double> cpu_seconds{};  ///< its CPU time (user + system)
  std::optional<long> max_rss_kb{};     ///< its peak resident set size, KiB

  /// Whether this transcript answers `input_text` as read by `tool` (any version).
  bool answers(std::string_view tool_name, std::string_view input_text) const;
};

/// The file a transcript is stored in: <sentence>.<tool>.out.
std::string transcript_file_name(std::string_view sentence, std::string_view tool);

/// The transcript as stored: header lines, then the output.
std::string to_text(const Transcript& transcript);

/// A stored transcript; nullopt when `text` has no valid header.
std::optional<Transcript> parse_transcript(const std::string& text);

/// The transcript stored in `file`; nullopt when the file is missing or has no valid header.
std::optional<Transcript> read_transcript(const std::filesystem::path& file);

/// Writes `transcript` to `file` through a temporary file renamed into place, so that an interrupted write
/// leaves the earlier transcript.
void write_transcript(const std::filesystem::path& file, const Transcript& transcript);

/// SHA-256 of `text`, lower-case hex (OpenSSL): `sha256sum FILE` prints the same.
std::string sha256_hex(std::string_view text);

}  // namespace affinterp::proofs
