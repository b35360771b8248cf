#pragma once
// Outputs are written to a staging folder and moved into place only when the whole run succeeded, so a
// failed run leaves earlier outputs intact.
#include <filesystem>

namespace affinterp {

class StagedOutput {
 public:
  /// Stages into a fresh hidden folder beside `target`.
  explicit StagedOutput(std::filesystem::path target);
  ~StagedOutput();  ///< discards the staging folder unless committed
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  /// Moves every staged file into `target` (same relative path, replacing what was there).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
};

}  // namespace affinterp
