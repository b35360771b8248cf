#include "experiments/support/staged_output.hpp"

#include <unistd.h>

#include <string>
#include <system_error>

namespace affinterp {

namespace fs = std::filesystem;

StagedOutput::StagedOutput(fs::path target) : target_(std::move(target)) {
  const fs::path parent = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
  std::string name = target_.filename().string();  // built by appending: GCC 12 misreports "." + s
  name.insert(name.begin(), '.');
  name += ".staging-" + std::to_string(getpid());
  staging_ = parent / name;
  fs::remove_all(staging_);
  fs::create_directories(staging_);
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedOutput::commit() {
  fs::create_directories(target_);
  for (const auto& entry : fs::recursive_directory_iterator(staging_)) {
    if (!entry.is_regular_file()) continue;
    const fs::path destination = target_ / fs::relative(entry.path(), staging_);
    fs::create_directories(destination.parent_path());
    fs::rename(entry.path(), destination);
  }
  fs::remove_all(staging_);
}

}  // namespace affinterp
