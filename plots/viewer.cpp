#include "plots/viewer.hpp"

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace affinterp::plots {

/// The page with the marker @AFFINTERP_DATA@ where the data go (plots/viewer/viewer.html, embedded at
/// build time by plots/viewer/embed.cmake).
extern const std::string_view viewer_page;

namespace {

static_assert(std::endian::native == std::endian::little && sizeof(int) == 4,
              "the page reads little-endian Int32 arrays");

std::string base64(const void* data, std::size_t size) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string text;
  text.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned n = bytes[i] << 16 | (i + 1 < size ? bytes[i + 1] << 8 : 0) | (i + 2 < size ? bytes[i + 2] : 0);
    text += digits[n >> 18 & 63];
    text += digits[n >> 12 & 63];
    text += i + 1 < size ? digits[n >> 6 & 63] : '=';
    text += i + 2 < size ? digits[n & 63] : '=';
  }
  return text;
}

/// Vertices as interleaved x, y Float32 values.
std::string float32(const Eigen::Matrix2Xd& vertices) {
  const Eigen::Matrix2Xf single = vertices.cast<float>();
  return base64(single.data(), sizeof(float) * static_cast<std::size_t>(single.size()));
}

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json run_json(const ViewerRun& run) {
  const auto n = run.frames.size();
  if (n == 0) throw std::invalid_argument("write_viewer: run '" + run.title + "' has no frames");
  if (run.times.size() != n || run.metrics.size() != n)
    throw std::invalid_argument("write_viewer: run '" + run.title + "' needs one time and one metrics entry per frame");
  for (const auto& frame : run.frames)
    if (frame.cols() != run.source.vertex_count())
      throw std::invalid_argument("write_viewer: run '" + run.title + "' has a frame of another vertex count");
  for (const auto& series : run.energy)
    if (series.values.size() != n)
      throw std::invalid_argument("write_viewer: energy '" + series.name + "' needs one value per frame");
  const Eigen::Matrix3Xi& triangles = run.source.triangles;
  nlohmann::json frames = nlohmann::json::array(), energy = nlohmann::json::array();
  for (const auto& frame : run.frames) frames.push_back(float32(frame));
  nlohmann::json metrics;
  for (const auto& m : run.metrics) {
    metrics["flipped_triangles"].push_back(m.flipped_triangles);
    metrics["min_det"].push_back(finite_or_null(m.min_det));
    metrics["max_det"].push_back(finite_or_null(m.max_det));
    metrics["max_distortion"].push_back(finite_or_null(m.max_distortion));
    metrics["mean_distortion"].push_back(finite_or_null(m.mean_distortion));
    metrics["area_ratio"].push_back(finite_or_null(m.area_ratio));
  }
  for (const auto& series : run.energy) {
    nlohmann::json values = nlohmann::json::array();
    for (const double x : series.values) values.push_back(finite_or_null(x));
    energy.push_back({{"name", series.name}, {"values", values}});
  }
  return {{"title", run.title},
          {"vertex_count", run.source.vertex_count()},
          {"triangle_count", triangles.cols()},
          {"triangles", base64(triangles.data(), sizeof(int) * static_cast<std::size_t>(triangles.size()))},
          {"rest", float32(run.source.vertices)},
          {"times", run.times},
          {"frames", frames},
          {"metrics", metrics},
          {"energy", energy}};
}

}  // namespace

void write_viewer(const std::filesystem::path& html, const std::string& title, const std::vector<ViewerRun>& runs) {
  if (runs.empty()) throw std::invalid_argument("write_viewer: no runs");
  nlohmann::json document = {{"title", title}, {"runs", nlohmann::json::array()}};
  for (const auto& run : runs) document["runs"].push_back(run_json(run));
  std::string data = document.dump();
  // '<' only occurs inside JSON strings, where \u003c means the same: no "</script>" can end the block.
  std::string escaped;
  escaped.reserve(data.size());
  for (const char c : data) c == '<' ? escaped += "\\u003c" : escaped += c;

  const std::string_view marker = "@AFFINTERP_DATA@";
  const auto at = viewer_page.find(marker);
  std::ofstream out(html, std::ios::binary);
  out << viewer_page.substr(0, at) << escaped << viewer_page.substr(at + marker.size());
  out.close();
  if (!out) throw std::runtime_error("cannot write " + html.string());
}

}  // namespace affinterp::plots
