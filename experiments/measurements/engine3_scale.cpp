#include "experiments/measurements/engine3_scale.hpp"

#include "experiments/bench/bootstrap.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace affinterp::measurements {

namespace {

/// `name`'s repetitions of `counter` in `file`, scaled by `unit`, against `limit`; nullopt when it did not run.
std::optional<Engine3Target> target_of(const std::filesystem::path& file, const std::string& counter, const char* name,
                                       double unit, double limit) {
  const auto results = bench::read_bench_results(file, counter);
  if (!results) return std::nullopt;
  const auto median = (*results)[name];
  const auto reps = results->repetitions.find(std::string_view(name));
  if (!median || reps == results->repetitions.end()) return std::nullopt;
  const std::vector<double> all = bench::pooled(reps->second);
  if (all.empty()) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(all.begin(), all.end());
  Engine3Target target{*median * unit, limit, {*lo * unit, *hi * unit}};
  target.verdict = claims::verdict_of(target.range, Interval{0, limit});
  return target;
}

nlohmann::json target_json(const Engine3Target& t) {
  return {{"median", t.median},
          {"limit", t.limit},
          {"range", interval_json(t.range)},
          {"verdict", verdict_json(t.verdict)}};
}

Engine3Target target_from(const nlohmann::json& json) {
  return {json.at("median"), json.at("limit"), optional_interval(json.at("range")).value_or(Interval{}),
          verdict_from(json.at("verdict"))};
}

}  // namespace

Engine3Scale engine3_scale_targets() {
  Engine3Scale scale;
  scale.setup_s.limit = 5, scale.frame_ms.limit = 250, scale.peak_MB.limit = 3072;
  return scale;
}

std::optional<Engine3Scale> engine3_scale(const std::filesystem::path& bench_file) {
  const auto results = bench::read_bench_results(bench_file, "ns_per_iteration");
  if (!results) return std::nullopt;
  Engine3Scale scale = engine3_scale_targets();
  const auto setup = target_of(bench_file, "ns_per_iteration", "3d-scale/setup/real_time", 1e-9, scale.setup_s.limit);
  const auto frame = target_of(bench_file, "ns_per_iteration", "3d-scale/frame/real_time", 1e-6, scale.frame_ms.limit);
  // The peak after the frames is the process's high-water mark over both benchmarks.
  const auto peak = target_of(bench_file, "peak_rss_mb", "3d-scale/frame/real_time", 1, scale.peak_MB.limit);
  if (!setup || !frame || !peak) return std::nullopt;
  scale.run = bench_run(*results);
  scale.setup_s = *setup, scale.frame_ms = *frame, scale.peak_MB = *peak;
  if (const auto triangles = bench::read_bench_results(bench_file, "triangles"))
    scale.triangles = (*triangles)["3d-scale/setup/real_time"].value_or(0);
  return scale;
}

void to_json(nlohmann::json& json, const Engine3Scale& scale) {
  json = nlohmann::json::object();
  write_run(json, scale.run);
  json["triangles"] = scale.triangles;
  json["setup_s"] = target_json(scale.setup_s);
  json["frame_ms"] = target_json(scale.frame_ms);
  json["peak_MB"] = target_json(scale.peak_MB);
}

void from_json(const nlohmann::json& json, Engine3Scale& scale) {
  scale.run = read_run(json);
  scale.triangles = json.value("triangles", 0.0);
  scale.setup_s = target_from(json.at("setup_s"));
  scale.frame_ms = target_from(json.at("frame_ms"));
  scale.peak_MB = target_from(json.at("peak_MB"));
}

}  // namespace affinterp::measurements
