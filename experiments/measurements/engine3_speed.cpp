#include "experiments/measurements/engine3_speed.hpp"

#include "experiments/bench/bootstrap.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace affinterp::measurements {

namespace {

/// bench_3d's benchmarks in the report's order, with what one iteration is and the target in ms (0: none).
struct RowSpec {
  const char* benchmark;
  const char* what;
  double limit_ms;
};
const std::array<RowSpec, 7> kRows{{
    {"3d/setup", "set-up (decompositions, rotation branches, E^F factorisation)", 200},
    {"3d/frame-1-thread", "one frame, one thread (CPU time)", 0},
    {"3d/frame-2-threads/real_time", "one frame, two threads (wall time)", 5},
    {"3d/blend3", "one frame of the blend of three poses, one thread", 0},
    {"3d/blend3-2-threads/real_time", "one frame of the blend of three poses, two threads (wall time)", 5},
    {"3d/arap-step", "one as-rigid-as-possible step on the middle frame (rotations and E^F's solve), one thread", 0},
    {"3d/stand-in", "one frame of the stand-in (theory/deformation), one thread", 0},
}};

std::optional<Engine3Row> row_of(const bench::BenchResults& results, const RowSpec& spec) {
  const char* name = spec.benchmark;
  const auto median = results[name];
  const auto reps = results.repetitions.find(std::string_view(name));
  if (!median || reps == results.repetitions.end()) return std::nullopt;
  const std::vector<double> all = bench::pooled(reps->second);
  if (all.empty()) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(all.begin(), all.end());
  Engine3Row row{name, spec.what, *median * 1e-6, {*lo * 1e-6, *hi * 1e-6}};
  if (spec.limit_ms > 0)
    row.limit_ms = spec.limit_ms, row.verdict = claims::verdict_of(row.range_ms, {0, spec.limit_ms});
  return row;
}

std::optional<Engine3Parts> parts_of(const std::filesystem::path& file) {
  Engine3Parts parts;
  const std::array<std::pair<const char*, double*>, 3> counters{{{"local_maps_ms", &parts.local_maps_ms},
                                                                 {"right_hand_side_ms", &parts.right_hand_side_ms},
                                                                 {"solve_ms", &parts.solve_ms}}};
  for (const auto& [counter, out] : counters) {
    const auto results = bench::read_bench_results(file, counter);
    const auto value = results ? (*results)["3d/frame-parts"] : std::nullopt;
    if (!value) return std::nullopt;
    *out = *value;
  }
  return parts;
}

}  // namespace

std::optional<Engine3Speed> engine3_speed(const std::filesystem::path& bench_file) {
  const auto results = bench::read_bench_results(bench_file, "ns_per_iteration");
  if (!results) return std::nullopt;
  Engine3Speed speed;
  speed.run = bench_run(*results);
  for (const RowSpec& spec : kRows)
    if (auto row = row_of(*results, spec)) speed.rows.push_back(std::move(*row));
  if (speed.rows.empty()) return std::nullopt;
  if (const auto triangles = bench::read_bench_results(bench_file, "triangles"))
    speed.triangles = (*triangles)["3d/setup"].value_or(0);
  speed.parts = parts_of(bench_file);
  return speed;
}

void to_json(nlohmann::json& json, const Engine3Speed& speed) {
  json = nlohmann::json::object();
  write_run(json, speed.run);
  json["triangles"] = speed.triangles;
  json["rows"] = nlohmann::json::array();
  for (const auto& row : speed.rows)
    json["rows"].push_back({{"benchmark", row.benchmark},
                            {"what", row.what},
                            {"median_ms", row.median_ms},
                            {"range_ms", interval_json(row.range_ms)},
                            {"limit_ms", row.limit_ms ? nlohmann::json(*row.limit_ms) : nlohmann::json()},
                            {"verdict", verdict_json(row.verdict)}});
  json["parts"] = speed.parts ? nlohmann::json{{"local_maps_ms", speed.parts->local_maps_ms},
                                               {"right_hand_side_ms", speed.parts->right_hand_side_ms},
                                               {"solve_ms", speed.parts->solve_ms}}
                              : nlohmann::json();
}

void from_json(const nlohmann::json& json, Engine3Speed& speed) {
  speed.run = read_run(json);
  speed.triangles = json.value("triangles", 0.0);
  speed.rows.clear();
  for (const auto& row : json.at("rows")) {
    const nlohmann::json limit = row.value("limit_ms", nlohmann::json());
    speed.rows.push_back({row.at("benchmark"), row.at("what"), row.at("median_ms"),
                          optional_interval(row.at("range_ms")).value_or(Interval{}),
                          limit.is_null() ? std::nullopt : std::optional<double>(limit.get<double>()),
                          optional_verdict(row.value("verdict", nlohmann::json()))});
  }
  const nlohmann::json& parts = json.value("parts", nlohmann::json());
  speed.parts.reset();
  if (!parts.is_null())
    speed.parts = Engine3Parts{parts.at("local_maps_ms"), parts.at("right_hand_side_ms"), parts.at("solve_ms")};
}

}  // namespace affinterp::measurements
