#pragma once
// The 3D engine's speed, from one run of build/bin/bench_3d (theory/global3 on the cat of Sumner and Popović 2004
// subdivided once, or CGAL's elephant subdivided twice): the set-up, a frame on one and two threads, a blend of three
// poses, an as-rigid-as-possible step and the deformation stand-in, each with the spread of its repetitions, and a
// frame's parts. Measurements, not claims. Three rows carry a target of the 3D engine's specification on 2 cores
// (set-up ≤ 0.2 s, a frame and a blend of three poses each ≥ 200 a second on two threads, i.e. ≤ 5 ms), decided on
// the spread of the repetitions as the scale targets are (scale_targets.hpp): met when every repetition meets it,
// missed when none does.
#include "experiments/measurements/bench_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::measurements {

/// One benchmark of the run: the median time of one iteration and the least and largest repetition.
struct Engine3Row {
  std::string benchmark;  ///< bench_3d's name, e.g. "3d/setup"
  std::string what;       ///< what one iteration is, in words
  double median_ms = 0;
  Interval range_ms;
  std::optional<double> limit_ms;  ///< the target, where the row has one
  std::optional<Verdict> verdict;  ///< with limit_ms
};

/// A frame's parts (FrameTimings, one thread): medians over the repetitions of 3d/frame-parts.
struct Engine3Parts {
  double local_maps_ms = 0, right_hand_side_ms = 0, solve_ms = 0;
};

struct Engine3Speed {
  BenchRun run;
  double triangles = 0;
  std::vector<Engine3Row> rows;
  std::optional<Engine3Parts> parts;
};

/// The record of `bench_file`; nullopt when it does not exist or its benchmarks did not run (no mesh).
std::optional<Engine3Speed> engine3_speed(const std::filesystem::path& bench_file);

/// claims.json's "engine3_speed": {"file", "date", "machine", "compiler", "flags", "triangles", "rows":
/// [{"benchmark", "what", "median_ms", "range_ms", "limit_ms", "verdict"}] (null without a target), "parts":
/// {"local_maps_ms", "right_hand_side_ms", "solve_ms"} or null}.
void to_json(nlohmann::json& json, const Engine3Speed& speed);
void from_json(const nlohmann::json& json, Engine3Speed& speed);

}  // namespace affinterp::measurements
