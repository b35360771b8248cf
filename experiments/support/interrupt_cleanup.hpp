#pragma once
// Nothing left behind by an interrupted run: child process groups registered here (the deciders) are
// killed and paths registered here (staging folders, partial files) removed when the process is ended by
// SIGINT, SIGTERM or SIGHUP, which then ends it by the same signal.
//
// The signal handler only records the signal and posts a semaphore (both async-signal-safe, POSIX
// signal-safety(7)); a thread waiting on the semaphore does the removal in ordinary context, restores the
// default action and raises the signal again, so the parent sees the process killed by it. Registration,
// removal and `settle` share one lock: a commit that has begun (moving staged files into place) finishes
// before the removal, and nothing is registered once the removal has begun.
#include <sys/types.h>

#include <filesystem>
#include <functional>

namespace affinterp {

/// Installs the handlers (once; a signal ignored at start, as under nohup, stays ignored). Call early in
/// main: without it, registrations are kept but nothing is removed on a signal.
void remove_registered_paths_on_interrupt();

/// Registers a file or folder for removal on interruption while this object lives.
class RemovedOnInterrupt {
 public:
  explicit RemovedOnInterrupt(std::filesystem::path path);
  ~RemovedOnInterrupt();
  RemovedOnInterrupt(const RemovedOnInterrupt&) = delete;
  RemovedOnInterrupt& operator=(const RemovedOnInterrupt&) = delete;

  /// Runs `action` (e.g. moving the path's contents into place) without an interruption's removal
  /// starting meanwhile, then unregisters the path.
  void settle(const std::function<void()>& action);

 private:
  std::filesystem::path path_;
  bool registered_ = true;
};

/// A child process that leads its own process group, killed with its group (SIGKILL) on interruption
/// while this object lives: an interrupted run leaves no decider running.
class KilledOnInterrupt {
 public:
  /// Runs `start`, which forks, puts the child in a process group of its own and returns its id, and
  /// registers the group, with no interruption's cleanup in between (a child started meanwhile would
  /// escape it).
  explicit KilledOnInterrupt(const std::function<pid_t()>& start);
  ~KilledOnInterrupt();
  KilledOnInterrupt(const KilledOnInterrupt&) = delete;
  KilledOnInterrupt& operator=(const KilledOnInterrupt&) = delete;

  pid_t pid() const { return pid_; }

 private:
  pid_t pid_;
};

}  // namespace affinterp
