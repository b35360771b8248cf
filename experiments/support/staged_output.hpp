#pragma once
// Outputs are written to a staging folder and moved into place only when the whole run succeeded, so a
// failed or interrupted run leaves earlier outputs intact and, with remove_registered_paths_on_interrupt()
// installed, no staging folder either (experiments/support/interrupt_cleanup.hpp). Staging folders that
// processes no longer running left behind (killed with SIGKILL, say) are removed by the next run.
#include "experiments/support/interrupt_cleanup.hpp"

#include <filesystem>
#include <optional>

namespace affinterp {

class StagedOutput {
 public:
  /// Stages into a fresh hidden folder beside `target`, `.NAME.staging-PID`, after removing those of
  /// `target` whose process is gone.
  explicit StagedOutput(std::filesystem::path target);
  ~StagedOutput();  ///< discards the staging folder unless committed
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  /// Moves every staged file into `target` (same relative path, replacing what was there); an
  /// interruption meanwhile waits until the move is done.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::optional<RemovedOnInterrupt> removed_on_interrupt_;
};

}  // namespace affinterp
