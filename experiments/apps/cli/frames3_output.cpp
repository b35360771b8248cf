#include "experiments/apps/cli/frames3_output.hpp"

#include "experiments/inputs/frame_metrics_json.hpp"
#include "experiments/inputs/mesh3_file.hpp"
#include "plots/viewer/viewer3.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace affinterp::cli {

namespace fs = std::filesystem;

namespace {

std::string frame3_name(int k, const global3::Mesh3& mesh) {
  std::ostringstream name;
  name << "frame_" << std::setw(4) << std::setfill('0') << k << io::mesh3_extension(mesh);
  return name.str();
}

}  // namespace

Frames3Output::Frames3Output(const fs::path& staging, const global3::Mesh3& reference, std::size_t frame_count,
                             const std::string& format, bool reoriented)
    : staging_(staging), frame_(reference), reference_(reference) {
  if (reoriented) frame_.elements.row(1).swap(frame_.elements.row(2));
  if (format == "npy") npy_.emplace(staging / "frames.npy", frame_count, reference.vertex_count(), 3);
}

nlohmann::json Frames3Output::record(int k, const Eigen::Matrix3Xd& vertices,
                                     std::span<const Eigen::Matrix3d> local_maps, bool quality) {
  nlohmann::json entry = {{"index", k}};
  if (npy_) {
    npy_->append(vertices);
    entry["file"] = "frames.npy";
  } else {
    frame_.vertices = vertices;
    entry["file"] = frame3_name(k, frame_);
    io::write_mesh3(frame_, staging_ / entry["file"].get<std::string>());
  }
  if (quality) {
    global3::FrameMetrics3 metrics = global3::frame_metrics3(reference_, vertices, local_maps, near_folds_);
    entry.update(io::metrics3_json(metrics, !near_folds_.empty()));
    inverted_.push_back(std::move(metrics.inverted));
  }
  return entry;
}

void Frames3Output::close() {
  if (npy_) npy_->close();
}

std::string inverted_summary(const nlohmann::json& frames, const std::string& whose) {
  long long most = 0, most_away = 0;
  bool folds = false;
  for (const auto& frame : frames) {
    if (!frame.contains("inverted_elements")) continue;
    const auto inverted = frame["inverted_elements"].get<long long>();
    folds = folds || frame.contains("inverted_near_folds");
    most = std::max(most, inverted);
    most_away = std::max(most_away, inverted - frame.value("inverted_near_folds", 0LL));
  }
  std::string summary = "most inverted elements in a frame: " + std::to_string(most);
  if (folds) summary += "; away from " + whose + " folds: " + std::to_string(most_away);
  return summary;
}

void write_viewer3_or_note(const fs::path& folder, const std::string& title, const global3::Mesh3& rest,
                           const std::vector<Eigen::Matrix3Xd>& frames, const std::vector<std::string>& labels,
                           const Frames3Output& measured) {
  const bool inverted = measured.inverted().size() == frames.size();
  std::vector<plots::Viewer3Frame> shown;
  for (std::size_t k = 0; k < frames.size(); ++k)
    shown.push_back({labels[k], frames[k], inverted ? std::optional(measured.inverted()[k]) : std::nullopt});
  try {
    plots::write_viewer3(folder / "viewer.html", title, rest, shown, measured.near_folds());
  } catch (const std::runtime_error& e) {
    std::cerr << "note: no viewer.html: " << e.what() << "\n";
  }
}

void commit_frames3(StagedOutput& staged, const fs::path& out) {
  std::error_code ignored;
  if (fs::is_directory(out))
    for (const auto& entry : fs::directory_iterator(out)) {
      const fs::path& file = entry.path();
      const std::string extension = file.extension().string();
      if ((file.filename().string().starts_with("frame_") && (extension == ".obj" || extension == ".mesh")) ||
          file.filename() == "frames.npy")
        fs::remove(file, ignored);
    }
  staged.commit();
}

}  // namespace affinterp::cli
