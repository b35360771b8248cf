#include "experiments/measurements/engine_cli.hpp"

#include "experiments/claims/speed_verdict.hpp"

#include <string>
#include <utility>

namespace affinterp::measurements {
namespace {

/// A frame through the CLI, writing included, within 1.3 times the engine's.
constexpr double target_ratio = 1.3;

/// The row of cli_frame/<energy>/<triangles> against engine_frame/<same>; nullopt without the engine's.
std::optional<CliRow> cli_row(const bench::BenchResults& times, const std::optional<bench::BenchResults>& extra,
                              const std::string& name, double cli_ms) {
  const std::string rest = name.substr(name.find('/') + 1), engine = "engine_frame/" + rest;
  const std::optional<double> engine_ms = times[engine];
  if (!engine_ms) return std::nullopt;
  CliRow row;
  row.energy = rest.substr(0, rest.find('/'));
  row.cli_frame_ms = cli_ms;
  row.engine_frame_ms = *engine_ms;
  row.extra_frames = extra ? (*extra)[name] : std::nullopt;
  row.ratio = claims::measured_ratio(times, name, engine);
  row.band = {0, target_ratio};
  row.verdict = claims::verdict_of(row.ratio, row.band);
  const std::string memory = "cli_frame_memory/" + rest;
  if ((row.cli_memory_frame_ms = times[memory])) {
    const bench::Measured memory_ratio = claims::measured_ratio(times, memory, engine);
    row.memory_ratio = memory_ratio.value;
    row.memory_ratio_ci95 = memory_ratio.ci95;
  }
  return row;
}

/// The ratio of a row as speed_verdict.hpp's to_json wrote it.
bench::Measured ratio_from(const nlohmann::json& row) {
  return {row.at("ratio").get<double>(), optional_interval(row.value("ratio_ci95", nlohmann::json())),
          row.value("repetitions", std::size_t{0}), row.value("processes", std::size_t{1})};
}

/// A band as to_json wrote it: [lo, hi], null for an unbounded side.
Interval band_from(const nlohmann::json& band) {
  return {optional_number(band.at(0)).value_or(-bench::kUnbounded),
          optional_number(band.at(1)).value_or(bench::kUnbounded)};
}

}  // namespace

std::optional<EngineCli> engine_cli(const std::filesystem::path& bench_file) {
  const std::optional<bench::BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return std::nullopt;
  const std::optional<bench::BenchResults> sizes = bench::read_bench_results(bench_file, "triangles");
  const std::optional<bench::BenchResults> extra = bench::read_bench_results(bench_file, "extra_frames");
  EngineCli cli{bench_run(*times), std::nullopt, target_ratio, {}, std::nullopt};
  std::vector<Verdict> verdicts;
  for (const auto& [name, cli_ms] : times->median) {
    if (!name.starts_with("cli_frame/")) continue;  // cli_frame/<energy>/<triangles>
    std::optional<CliRow> row = cli_row(*times, extra, name, cli_ms);
    if (!row) continue;
    if (const auto triangles = sizes ? (*sizes)[name] : std::nullopt) cli.triangles = *triangles;
    verdicts.push_back(row->verdict);
    cli.rows.push_back(std::move(*row));
  }
  if (!verdicts.empty()) cli.verdict = claims::all_of(verdicts);
  return cli;
}

void to_json(nlohmann::json& json, const EngineCli& cli) {
  json = {
      {"target_ratio", cli.target_ratio}, {"rows", nlohmann::json::array()}, {"verdict", verdict_json(cli.verdict)}};
  write_run(json, cli.run);
  if (cli.triangles) json["triangles"] = *cli.triangles;
  for (const CliRow& r : cli.rows) {
    nlohmann::json row = claims::to_json(r.ratio, r.band);  // ratio, its interval, band, repetitions, verdict
    row["energy"] = r.energy;
    row["cli_frame_ms"] = r.cli_frame_ms;
    row["engine_frame_ms"] = r.engine_frame_ms;
    if (r.extra_frames) row["extra_frames"] = *r.extra_frames;
    if (r.cli_memory_frame_ms) row["cli_memory_frame_ms"] = *r.cli_memory_frame_ms;
    if (r.memory_ratio) {
      row["memory_ratio"] = *r.memory_ratio;
      row["memory_ratio_ci95"] = interval_json(r.memory_ratio_ci95);
    }
    json["rows"].push_back(std::move(row));
  }
}

void from_json(const nlohmann::json& json, EngineCli& cli) {
  cli = {read_run(json),
         optional_number(json.value("triangles", nlohmann::json())),
         json.at("target_ratio").get<double>(),
         {},
         optional_verdict(json.value("verdict", nlohmann::json()))};
  for (const auto& row : json.at("rows")) {
    CliRow r;
    r.energy = row.at("energy");
    r.cli_frame_ms = row.at("cli_frame_ms");
    r.engine_frame_ms = row.at("engine_frame_ms");
    r.extra_frames = optional_number(row.value("extra_frames", nlohmann::json()));
    r.ratio = ratio_from(row);
    r.band = band_from(row.at("band"));
    r.verdict = verdict_from(row.at("verdict"));
    r.cli_memory_frame_ms = optional_number(row.value("cli_memory_frame_ms", nlohmann::json()));
    r.memory_ratio = optional_number(row.value("memory_ratio", nlohmann::json()));
    r.memory_ratio_ci95 = optional_interval(row.value("memory_ratio_ci95", nlohmann::json()));
    cli.rows.push_back(std::move(r));
  }
}

}  // namespace affinterp::measurements
