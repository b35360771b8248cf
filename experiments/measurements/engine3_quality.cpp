#include "experiments/measurements/engine3_quality.hpp"

#include "theory/deformation/deformation.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/interpolation3.hpp"
#include "theory/global3/target_folds3.hpp"
#include "theory/sym3/algorithms.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace affinterp::measurements {

namespace {

using global::LocalHomotopy;
using global3::Interpolation3;
using global3::Interpolation3Options;
using global3::Mesh3;

/// The as-rigid-as-possible row's steps a frame (arap_refinement3.hpp): enough to see where the iteration heads.
constexpr int arap_steps = 5;

/// A way of making frames: the frames of one pair at the given times.
struct Method {
  std::string name;
  std::function<std::vector<Eigen::Matrix3Xd>(const PosePair&, const std::vector<double>&)> frames;
};

/// Interpolation3 with the defaults (exp-log, consistent branches, E^F alone) changed by `set`.
Method engine_method(std::string name, const std::function<void(Interpolation3Options&)>& set) {
  Interpolation3Options options;
  set(options);
  return {std::move(name), [=](const PosePair& pair, const std::vector<double>& times) {
            return Interpolation3(pair.source, pair.target, options).vertices_at(times);
          }};
}

std::vector<Method> methods() {
  using global::RotationBranch;
  std::vector<Method> all{
      {"per-vertex linear blend",
       [](const PosePair& pair, const std::vector<double>& times) {
         std::vector<Eigen::Matrix3Xd> frames;
         for (double t : times) frames.push_back((1 - t) * pair.source.vertices + t * pair.target.vertices);
         return frames;
       }},
      {"stand-in (theory/deformation)",
       [](const PosePair& pair, const std::vector<double>& times) {
         const auto surface = [](const Mesh3& m) { return sym3::Mesh3{m.vertices, m.elements}; };
         sym3::Deformation3 deformation(surface(pair.source), surface(pair.target));
         std::vector<Eigen::Matrix3Xd> frames;
         for (double t : times) frames.push_back(deformation.interpolate(t, sym3::exp_batched));
         return frames;
       }},
  };
  for (auto [name, homotopy] : {std::pair{"E^F, linear", LocalHomotopy::linear},
                                {"E^F, polar", LocalHomotopy::polar},
                                {"E^F, SVD", LocalHomotopy::svd}})
    all.push_back(engine_method(name, [homotopy](auto& o) { o.homotopy = homotopy; }));
  all.push_back(
      engine_method("E^F, exp-log, principal branch", [](auto& o) { o.rotation_branch = RotationBranch::principal; }));
  all.push_back(engine_method("E^F, exp-log", [](auto&) {}));
  all.push_back(engine_method("E^F, exp-log, symmetrised", [](auto& o) { o.symmetric = true; }));
  all.push_back(engine_method("exp-log, " + std::to_string(arap_steps) + " as-rigid-as-possible steps",
                              [](auto& o) { o.arap_iterations = arap_steps; }));
  return all;
}

/// The method E^F exp-log with Interpolation3's defaults, whose frames the close-up shows.
constexpr std::string_view exp_log_method = "E^F, exp-log";

/// A method's frames on one pair: its cell, and the frame with the most inverted elements away from the target's
/// folds (then the most inverted; the first such).
struct Measured {
  Engine3QualityCell cell;
  std::size_t worst = 0;
  long worst_away = 0, worst_inverted = 0;  ///< that frame's counts
};

/// The frames' cell, against the reference's local maps at each frame's time (`reference[f]`), with `near` the
/// elements at or beside the target's folds.
Measured measured(const PosePair& pair, const std::vector<Eigen::Matrix3Xd>& frames, const std::vector<double>& times,
                  const std::vector<std::vector<Eigen::Matrix3d>>& reference, const std::vector<unsigned char>& near) {
  Measured m;
  Engine3QualityCell& cell = m.cell;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const global3::FrameMetrics3 metrics = global3::frame_metrics3(pair.source, frames[f], reference[f], near);
    const long inverted = metrics.inverted_elements, away = inverted - metrics.inverted_near_folds;
    if (inverted > cell.most_inverted) cell.most_inverted = inverted, cell.at_t = times[f];
    cell.most_inverted_away = std::max(cell.most_inverted_away, away);
    if (std::pair(away, inverted) > std::pair(m.worst_away, m.worst_inverted))
      m.worst = f, m.worst_away = away, m.worst_inverted = inverted;
    if (f == frames.size() / 2) cell.middle_distortion = metrics.mean_distortion;
  }
  return m;
}

}  // namespace

Engine3Quality engine3_quality(const std::vector<PosePair>& pairs, int frames,
                               const std::function<void(const std::string&)>& progress) {
  if (frames < 2) throw std::invalid_argument("engine3_quality: at least two frames");
  std::vector<double> times;
  for (int f = 0; f < frames; ++f) times.push_back(static_cast<double>(f) / (frames - 1));
  const std::vector<Method> all = methods();
  Engine3Quality quality;
  quality.frames = frames;
  for (const Method& method : all) quality.methods.push_back(method.name);
  quality.cells.assign(all.size(), {});
  for (const PosePair& pair : pairs) {
    if (progress) progress(pair.name);
    quality.pairs.push_back(pair.name);
    quality.elements.push_back(static_cast<long>(pair.source.element_count()));
    const std::vector<Eigen::Index> folds = global3::target_folds(pair.source, pair.target);
    quality.target_folds.push_back(static_cast<long>(folds.size()));
    const std::vector<unsigned char> near = global3::near_folds(pair.source, folds);
    // One reference for every method: exp-log's local maps on consistent branches, at each frame's time.
    const Interpolation3 exp_log(pair.source, pair.target);
    std::vector<std::vector<Eigen::Matrix3d>> reference;
    for (const double t : times) reference.push_back(exp_log.local_maps_at(t));
    for (std::size_t m = 0; m < all.size(); ++m) {
      const std::vector<Eigen::Matrix3Xd> frames_of_method = all[m].frames(pair, times);
      const Measured cell = measured(pair, frames_of_method, times, reference, near);
      quality.cells[m].push_back(cell.cell);
      if (all[m].name != exp_log_method || cell.cell.most_inverted == 0) continue;
      const bool worse = !quality.closeup || std::pair(cell.worst_away, cell.worst_inverted) >
                                                 std::pair(quality.closeup->inverted_away, quality.closeup->inverted);
      if (worse)
        quality.closeup = closeup_of_frame(pair.name, pair.source, pair.target, times[cell.worst],
                                           frames_of_method[cell.worst], reference[cell.worst]);
    }
  }
  return quality;
}

std::optional<Engine3Quality> read_engine3_quality(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  nlohmann::json json;
  try {
    in >> json;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  return json.get<Engine3Quality>();
}

void to_json(nlohmann::json& json, const Engine3Quality& quality) {
  json = {{"frames", quality.frames},
          {"pairs", quality.pairs},
          {"elements", quality.elements},
          {"target_folds", quality.target_folds},
          {"methods", quality.methods},
          {"cells", nlohmann::json::array()},
          {"closeup", quality.closeup ? nlohmann::json(*quality.closeup) : nlohmann::json()},
          {"figures", quality.figures}};
  for (const auto& row : quality.cells) {
    nlohmann::json cells = nlohmann::json::array();
    for (const Engine3QualityCell& c : row)
      cells.push_back({{"most_inverted", c.most_inverted},
                       {"most_inverted_away", c.most_inverted_away},
                       {"at_t", c.at_t},
                       {"middle_distortion", c.middle_distortion}});
    json["cells"].push_back(cells);
  }
}

void from_json(const nlohmann::json& json, Engine3Quality& quality) {
  quality.frames = json.at("frames");
  quality.pairs = json.at("pairs").get<std::vector<std::string>>();
  quality.elements = json.at("elements").get<std::vector<long>>();
  // A record written before the target's folds were counted has neither them nor the count away from them.
  quality.target_folds = json.value("target_folds", std::vector<long>{});
  quality.methods = json.at("methods").get<std::vector<std::string>>();
  quality.closeup.reset();
  if (json.contains("closeup") && !json["closeup"].is_null()) quality.closeup = json["closeup"].get<Engine3Closeup>();
  quality.figures = json.value("figures", std::vector<std::string>{});
  quality.cells.clear();
  for (const auto& row : json.at("cells")) {
    quality.cells.emplace_back();
    for (const auto& c : row)
      quality.cells.back().push_back({c.at("most_inverted"),
                                      c.value("most_inverted_away", c.at("most_inverted").get<long>()), c.at("at_t"),
                                      c.at("middle_distortion")});
  }
}

}  // namespace affinterp::measurements
