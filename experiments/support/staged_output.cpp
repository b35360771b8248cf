#include "experiments/support/staged_output.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace affinterp {

namespace fs = std::filesystem;

namespace {

/// True when `name` is PREFIX followed by the id of a process that no longer exists (kill(pid, 0)
/// reports ESRCH; a live process of another user answers EPERM and is left alone).
bool left_by_a_gone_process(const std::string& name, const std::string& prefix) {
  if (!name.starts_with(prefix) || name.size() == prefix.size() || name.size() - prefix.size() > 9) return false;
  for (std::size_t i = prefix.size(); i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  const pid_t pid = static_cast<pid_t>(std::stol(name.substr(prefix.size())));
  return pid > 0 && pid != getpid() && kill(pid, 0) == -1 && errno == ESRCH;
}

}  // namespace

StagedOutput::StagedOutput(fs::path target) : target_(std::move(target)) {
  const fs::path parent = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
  std::string prefix = target_.filename().string();  // built by appending: GCC 12 misreports "." + s
  prefix.insert(prefix.begin(), '.');
  prefix += ".staging-";
  std::error_code ignored;
  for (const auto& entry : fs::directory_iterator(parent, ignored))
    if (left_by_a_gone_process(entry.path().filename().string(), prefix)) fs::remove_all(entry.path(), ignored);
  staging_ = parent / (prefix + std::to_string(getpid()));
  removed_on_interrupt_.emplace(staging_);
  fs::remove_all(staging_);
  fs::create_directories(staging_);
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedOutput::commit() {
  removed_on_interrupt_->settle([this] {
    fs::create_directories(target_);
    for (const auto& entry : fs::recursive_directory_iterator(staging_)) {
      if (!entry.is_regular_file()) continue;
      const fs::path destination = target_ / fs::relative(entry.path(), staging_);
      fs::create_directories(destination.parent_path());
      fs::rename(entry.path(), destination);
    }
    fs::remove_all(staging_);
  });
}

}  // namespace affinterp
