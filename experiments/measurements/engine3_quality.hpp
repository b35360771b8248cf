#pragma once
// The 3D engine's frames against baselines: for each pose pair and each way of making frames, the most elements
// inverted in one frame and the elements' distortion, over frames at t = 0, 1/(N−1), …, 1. Measurements, not claims:
// the wish of no inverted triangle on the cat pairs is a target this table shows met or not, per method.
//
// Methods: the per-vertex linear blend (1 − t)P + tQ; the deformation application's stand-in (theory/deformation:
// exp-log on principal rotations, edge form, vertex 0 anchored); Interpolation3 with E^F and each local homotopy
// (linear, polar, SVD, exp-log on principal and on consistent rotation branches), exp-log symmetrised, and exp-log
// with as-rigid-as-possible steps on each frame (arap_refinement3.hpp: the 3D counterpart of E^R without its scale).
//
// Inversion is measured against one reference for every method, so that the rows compare: the exp-log local maps
// A_i(t) on consistent branches (frame_metrics3.hpp: a triangle whose normal opposes A_i(t) n_p). Distortion: the
// mean over elements of σ1/σ2 of each element's in-plane map (σ1/σ3 for tetrahedra) in the frame nearest t = 1/2
// (at the ends every method gives the poses themselves, whose distortion is the target's).
#include "experiments/measurements/engine3_closeup.hpp"
#include "theory/global3/mesh3.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// Two compatible poses, named for the report ("cat-0 → cat-4").
struct PosePair {
  std::string name;
  global3::Mesh3 source, target;
};

/// One method on one pair: the most elements inverted in a frame (the first such frame's t), the most inverted in a
/// frame away from the target's folds (neither a fold nor sharing a vertex with one: target_folds3.hpp), the middle
/// frame's mean distortion.
struct Engine3QualityCell {
  long most_inverted = 0;
  long most_inverted_away = 0;
  double at_t = 0;
  double middle_distortion = 0;
};

struct Engine3Quality {
  int frames = 0;
  std::vector<std::string> pairs;    ///< the pairs' names
  std::vector<long> elements;        ///< each pair's element count
  std::vector<long> target_folds;    ///< each pair's triangles the target folds (the input's); empty in older records
  std::vector<std::string> methods;  ///< each method's name, e.g. "E^F, exp-log, symmetrised"
  std::vector<std::vector<Engine3QualityCell>> cells;  ///< cells[method][pair]
  /// E^F exp-log's frame (Interpolation3's defaults) with the most inverted triangles away from its target's folds
  /// (then the most inverted), over every pair, up close; none when no such frame inverts a triangle.
  std::optional<Engine3Closeup> closeup;
  std::vector<std::string> figures;  ///< the close-up drawn (draw_engine3_closeup), when the report draws figures
};

/// Every method on every pair at `frames` frames; `progress` is told each pair's name as it starts.
Engine3Quality engine3_quality(const std::vector<PosePair>& pairs, int frames,
                               const std::function<void(const std::string&)>& progress = {});

/// The record in `file` (written by quality_3d), or nullopt when there is none.
std::optional<Engine3Quality> read_engine3_quality(const std::filesystem::path& file);

/// claims.json's "engine3_quality": {"frames", "pairs", "elements", "target_folds", "methods", "cells":
/// [[{"most_inverted", "most_inverted_away", "at_t", "middle_distortion"}]], "closeup" (or null), "figures"}.
void to_json(nlohmann::json& json, const Engine3Quality& quality);
void from_json(const nlohmann::json& json, Engine3Quality& quality);

}  // namespace affinterp::measurements
