#pragma once
// The project's real meshes (../shared/data/meshes beside the checkout), which users do not have: tests
// that use them skip with "skipped: ../shared not present" when absent.
#include <filesystem>
#include <optional>

namespace affinterp::checks {

inline std::optional<std::filesystem::path> shared_meshes() {
  const std::filesystem::path folder(AFFINTERP_SOURCE_DIR "/../shared/data/meshes");
  if (std::filesystem::exists(folder / "man0.obj")) return folder;
  return std::nullopt;
}

}  // namespace affinterp::checks
