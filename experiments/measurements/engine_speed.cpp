#include "experiments/measurements/engine_speed.hpp"

#include "experiments/bench/machine_label.hpp"
#include "experiments/bench/pooled.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <set>
#include <string>
#include <utility>

namespace affinterp::measurements {
namespace {

using bench::BenchResults;
using bench::Measured;
using claims::verdict_of;

constexpr double specified_setup_ms = 200.0;  // the engine specification's set-up target

std::optional<double> frames_per_second_target(const std::string& energy) {
  if (energy == "F") return 150.0;
  if (energy == "R") return 25.0;
  return std::nullopt;
}

/// The raised targets on the octopus: E^F ≥ 300, E^R ≥ 60 frames/s, one frame at a time or batched.
std::optional<double> raised_frames_per_second_target(const std::string& energy) {
  if (energy == "F") return 300.0;
  if (energy == "R") return 60.0;
  return std::nullopt;
}

/// Where a frame's time goes, from the run's frame_rhs, frame_assembly, frame_factor and frame_solve rows
/// (bench_interp: the parts of a frame as vertices_at(t) runs them), when it has them.
std::optional<FrameParts> frame_parts(const BenchResults& times, const std::optional<BenchResults>& threads,
                                      const std::string& rest, double frame_ms) {
  const std::optional<double> solve = times["frame_solve/" + rest];
  if (!solve) return std::nullopt;
  FrameParts parts{times["frame_rhs/" + rest],
                   times["frame_assembly/" + rest],
                   times["frame_factor/" + rest],
                   *solve,
                   threads ? (*threads)["frame_solve/" + rest] : std::nullopt,
                   frame_ms - *solve};
  for (const std::optional<double>& ms : {parts.right_hand_side_ms, parts.assembly_ms, parts.factor_ms})
    if (ms) parts.rest_ms -= *ms;
  return parts;
}

double identity(double x) { return x; }
double per_second(double ms) { return 1000.0 / ms; }
/// bench_interp's batch_frames: 8 frames per iteration (engine_bench.hpp).
double batch_per_second(double ms) { return 8000.0 / ms; }

/// One energy's targets: met (reproduced) iff the set-up's and the frame rate's intervals lie in their bands;
/// inconclusive without a set-up time.
Verdict targets_verdict(const std::optional<Measured>& setup, const Measured& frames_per_s, const std::string& energy) {
  if (!setup) return Verdict::inconclusive;
  return claims::all_of({verdict_of(*setup, {0, specified_setup_ms}),
                         verdict_of(frames_per_s, {frames_per_second_target(energy).value_or(0), bench::kUnbounded})});
}

/// The row of frame/<energy>/<mesh> (`rest` is <energy>/<mesh>).
SpeedRow speed_row(const BenchResults& times, const std::optional<BenchResults>& threads, const std::string& rest,
                   double frame_ms) {
  SpeedRow row;
  row.energy = rest.substr(0, rest.find('/'));
  row.setup_ms = times["setup/" + rest];
  row.setup_target_ms = specified_setup_ms;
  row.frame_ms = frame_ms;
  row.frames_per_s = claims::measured_median(times, "frame/" + rest, per_second);
  std::optional<Measured> setup;
  if (row.setup_ms) setup = claims::measured_median(times, "setup/" + rest, identity);
  if (setup) row.setup_ms_ci95 = setup->ci95;
  row.target_frames_per_s = frames_per_second_target(row.energy);
  row.baseline_ms = times["frame_refactor/" + rest];
  if (row.baseline_ms) row.speedup_vs_baseline = *row.baseline_ms / frame_ms;
  row.verdict = targets_verdict(setup, row.frames_per_s, row.energy);
  std::optional<Measured> batched;
  if (times["batch_frames/" + rest]) batched = claims::measured_median(times, "batch_frames/" + rest, batch_per_second);
  if (batched) {
    row.batched_frames_per_s = batched->value;
    row.batched_frames_per_s_ci95 = batched->ci95;
  }
  row.raised_target_frames_per_s = raised_frames_per_second_target(row.energy);
  if (const std::optional<double> raised = row.raised_target_frames_per_s) {
    row.raised_verdict = verdict_of(row.frames_per_s, {*raised, bench::kUnbounded});
    if (batched) row.raised_verdict_batched = verdict_of(*batched, {*raised, bench::kUnbounded});
  }
  row.frame_parts = frame_parts(times, threads, rest, frame_ms);
  return row;
}

nlohmann::json to_json(const FrameParts& p) {
  return {{"right_hand_side_ms", optional_json(p.right_hand_side_ms)},
          {"assembly_ms", optional_json(p.assembly_ms)},
          {"factor_ms", optional_json(p.factor_ms)},
          {"solve_ms", p.solve_ms},
          {"threads", optional_json(p.threads)},
          {"rest_ms", p.rest_ms}};
}

FrameParts frame_parts_from(const nlohmann::json& p) {
  return {optional_number(p.at("right_hand_side_ms")),
          optional_number(p.at("assembly_ms")),
          optional_number(p.at("factor_ms")),
          p.at("solve_ms").get<double>(),
          optional_number(p.at("threads")),
          p.at("rest_ms").get<double>()};
}

nlohmann::json to_json(const SpeedRow& r) {
  return {{"energy", r.energy},
          {"setup_ms", optional_json(r.setup_ms)},
          {"setup_ms_ci95", interval_json(r.setup_ms_ci95)},
          {"setup_target_ms", r.setup_target_ms},
          {"frame_ms", r.frame_ms},
          {"frames_per_s", r.frames_per_s.value},
          {"frames_per_s_ci95", interval_json(r.frames_per_s.ci95)},
          {"target_frames_per_s", optional_json(r.target_frames_per_s)},
          {"repetitions", r.frames_per_s.repetitions},
          {"processes", r.frames_per_s.processes},
          {"baseline_ms", optional_json(r.baseline_ms)},
          {"speedup_vs_baseline", optional_json(r.speedup_vs_baseline)},
          {"verdict", claims::to_string(r.verdict)},
          {"batched_frames_per_s", optional_json(r.batched_frames_per_s)},
          {"batched_frames_per_s_ci95", interval_json(r.batched_frames_per_s_ci95)},
          {"raised_target_frames_per_s", optional_json(r.raised_target_frames_per_s)},
          {"raised_verdict", verdict_json(r.raised_verdict)},
          {"raised_verdict_batched", verdict_json(r.raised_verdict_batched)},
          {"frame_parts", r.frame_parts ? to_json(*r.frame_parts) : nlohmann::json()}};
}

SpeedRow speed_row_from(const nlohmann::json& j) {
  SpeedRow r;
  r.energy = j.at("energy");
  r.setup_ms = optional_number(j.at("setup_ms"));
  r.setup_ms_ci95 = optional_interval(j.at("setup_ms_ci95"));
  r.setup_target_ms = j.at("setup_target_ms");
  r.frame_ms = j.at("frame_ms");
  r.frames_per_s = {j.at("frames_per_s"), optional_interval(j.at("frames_per_s_ci95")), j.at("repetitions"),
                    j.at("processes")};
  r.target_frames_per_s = optional_number(j.at("target_frames_per_s"));
  r.baseline_ms = optional_number(j.at("baseline_ms"));
  r.speedup_vs_baseline = optional_number(j.at("speedup_vs_baseline"));
  r.verdict = verdict_from(j.at("verdict"));
  r.batched_frames_per_s = optional_number(j.value("batched_frames_per_s", nlohmann::json()));
  r.batched_frames_per_s_ci95 = optional_interval(j.value("batched_frames_per_s_ci95", nlohmann::json()));
  r.raised_target_frames_per_s = optional_number(j.value("raised_target_frames_per_s", nlohmann::json()));
  r.raised_verdict = optional_verdict(j.value("raised_verdict", nlohmann::json()));
  r.raised_verdict_batched = optional_verdict(j.value("raised_verdict_batched", nlohmann::json()));
  const nlohmann::json parts = j.value("frame_parts", nlohmann::json());
  if (parts.is_object()) r.frame_parts = frame_parts_from(parts);
  return r;
}

/// One energy of one recorded run (`rest` is <energy>/<mesh>), decided alone.
RunSpeed run_speed(const bench::RecordedRun& run, const std::string& rest, const bench::Figure& figure) {
  RunSpeed row;
  row.run = run.id;
  row.date = run.date;
  row.cpu = bench::machine_label(run.machine);
  row.energy = rest.substr(0, rest.find('/'));
  row.mesh = rest.substr(rest.find('/') + 1);
  row.recorded = run.recorded;
  if (const nlohmann::json cores = run.machine.value("cores", nlohmann::json()); cores.is_number())
    row.cores = cores.get<long>();
  row.frames_per_s = figure.measured;
  row.target_frames_per_s = frames_per_second_target(row.energy);
  if (const auto setup = run.figures.find(bench::setup_key(rest)); setup != run.figures.end())
    row.setup_ms = setup->second.measured;
  row.verdict = targets_verdict(row.setup_ms, figure.measured, row.energy);
  return row;
}

nlohmann::json to_json(const RunSpeed& r) {
  return {{"run", r.run},
          {"recorded", r.recorded},
          {"date", r.date},
          {"cpu", r.cpu},
          {"cores", r.cores ? nlohmann::json(*r.cores) : nlohmann::json()},
          {"energy", r.energy},
          {"mesh", r.mesh},
          {"frames_per_s", r.frames_per_s.value},
          {"frames_per_s_ci95", interval_json(r.frames_per_s.ci95)},
          {"target_frames_per_s", optional_json(r.target_frames_per_s)},
          {"setup_ms", r.setup_ms ? nlohmann::json(r.setup_ms->value) : nlohmann::json()},
          {"setup_ms_ci95", r.setup_ms ? interval_json(r.setup_ms->ci95) : nlohmann::json()},
          {"processes", r.frames_per_s.processes},
          {"verdict", claims::to_string(r.verdict)}};
}

RunSpeed run_speed_from(const nlohmann::json& j) {
  RunSpeed r;
  r.run = j.at("run");
  r.date = j.at("date");
  r.cpu = j.value("cpu", "?");
  r.energy = j.at("energy");
  r.mesh = j.at("mesh");
  r.recorded = j.value("recorded", true);
  if (j.at("cores").is_number()) r.cores = j["cores"].get<long>();
  r.frames_per_s = {j.at("frames_per_s"), optional_interval(j.at("frames_per_s_ci95")), 0, j.at("processes")};
  r.target_frames_per_s = optional_number(j.at("target_frames_per_s"));
  if (j.at("setup_ms").is_number())
    r.setup_ms = Measured{j["setup_ms"].get<double>(), optional_interval(j.at("setup_ms_ci95")), 0, 1};
  r.verdict = verdict_from(j.at("verdict"));
  return r;
}

/// The pooled row of frame/<energy>/<mesh> (`rest` is <energy>/<mesh>) on `machine`, when one of its runs
/// measured it.
std::optional<MachineSpeed> machine_speed(const bench::MachineRuns& machine, const std::string& rest) {
  const std::optional<Measured> frames = bench::pooled_figure(machine, "frame/" + rest);
  if (!frames) return std::nullopt;
  MachineSpeed row{bench::machine_label(machine.runs.front()->machine),
                   rest.substr(0, rest.find('/')),
                   rest.substr(rest.find('/') + 1),
                   machine.runs.size(),
                   *frames,
                   bench::pooled_figure(machine, bench::setup_key(rest))};
  row.verdict = targets_verdict(row.setup_ms, row.frames_per_s, row.energy);
  return row;
}

nlohmann::json to_json(const MachineSpeed& m) {
  return {{"machine", m.machine},
          {"energy", m.energy},
          {"mesh", m.mesh},
          {"runs", m.runs},
          {"frames_per_s", m.frames_per_s.value},
          {"frames_per_s_ci95", interval_json(m.frames_per_s.ci95)},
          {"setup_ms", m.setup_ms ? nlohmann::json(m.setup_ms->value) : nlohmann::json()},
          {"setup_ms_ci95", m.setup_ms ? interval_json(m.setup_ms->ci95) : nlohmann::json()},
          {"verdict", claims::to_string(m.verdict)}};
}

MachineSpeed machine_speed_from(const nlohmann::json& j) {
  MachineSpeed m{j.at("machine"), j.at("energy"), j.at("mesh"), j.at("runs"), {}, {}};
  m.frames_per_s = {j.at("frames_per_s"), optional_interval(j.at("frames_per_s_ci95")), 0, 1};
  if (j.at("setup_ms").is_number())
    m.setup_ms = Measured{j["setup_ms"].get<double>(), optional_interval(j.at("setup_ms_ci95")), 0, 1};
  m.verdict = verdict_from(j.at("verdict"));
  return m;
}

nlohmann::json to_json(const SpeedHistory& h) {
  nlohmann::json rows = nlohmann::json::array(), machines = nlohmann::json::array(), across = nlohmann::json::object();
  for (const RunSpeed& row : h.rows) rows.push_back(to_json(row));
  for (const MachineSpeed& row : h.machines) machines.push_back(to_json(row));
  for (const auto& [energy, verdict] : h.across_machines) across[energy] = claims::to_string(verdict);
  return {{"rows", rows}, {"machines", machines}, {"across_machines", across}, {"rule", h.rule}};
}

SpeedHistory history_from(const nlohmann::json& j) {
  SpeedHistory h{{}, {}, {}, j.value("rule", "")};
  for (const auto& row : j.at("rows")) h.rows.push_back(run_speed_from(row));
  const nlohmann::json machines = j.value("machines", nlohmann::json::array()),
                       across = j.value("across_machines", nlohmann::json::object());
  for (const auto& row : machines) h.machines.push_back(machine_speed_from(row));
  for (const auto& [energy, verdict] : across.items()) h.across_machines[energy] = verdict_from(verdict);
  return h;
}

}  // namespace

std::optional<EngineSpeed> engine_speed(const std::filesystem::path& bench_file) {
  const std::optional<BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return std::nullopt;
  const std::optional<BenchResults> sizes = bench::read_bench_results(bench_file, "triangles");
  const std::optional<BenchResults> threads = bench::read_bench_results(bench_file, "threads");
  EngineSpeed speed;
  speed.run = bench_run(*times);
  for (const auto& [name, frame_ms] : times->median) {
    if (!name.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
    const std::string rest = name.substr(6);
    speed.mesh = rest.substr(rest.find('/') + 1);
    if (const auto triangles = sizes ? (*sizes)["setup/" + rest] : std::nullopt) speed.triangles = *triangles;
    speed.rows.push_back(speed_row(*times, threads, rest, frame_ms));
  }
  return speed;
}

SpeedHistory engine_speed_history(const std::vector<bench::RecordedRun>& runs) {
  SpeedHistory history{{}, {}, {}, std::string(claims::kAcrossMachinesRule)};
  std::set<std::string> rests;  // <energy>/<mesh> of every frame figure
  for (const bench::RecordedRun& run : runs)
    for (const auto& [key, figure] : run.figures) {
      if (!key.starts_with("frame/")) continue;  // frame/<energy>/<mesh>
      history.rows.push_back(run_speed(run, key.substr(6), figure));
      rests.insert(key.substr(6));
    }
  std::map<std::string, std::vector<Verdict>> by_energy;
  for (const bench::MachineRuns& machine : bench::by_machine(runs))
    for (const std::string& rest : rests)
      if (const std::optional<MachineSpeed> row = machine_speed(machine, rest)) {
        history.machines.push_back(*row);
        by_energy[row->energy].push_back(row->verdict);
      }
  for (const auto& [energy, verdicts] : by_energy) history.across_machines[energy] = claims::across_machines(verdicts);
  return history;
}

void to_json(nlohmann::json& json, const EngineSpeed& speed) {
  json = {{"rows", nlohmann::json::array()}};
  write_run(json, speed.run);
  if (!speed.mesh.empty()) json["mesh"] = speed.mesh;
  if (speed.triangles) json["triangles"] = *speed.triangles;
  for (const SpeedRow& row : speed.rows) json["rows"].push_back(to_json(row));
  if (speed.history) json["history"] = to_json(*speed.history);
}

void from_json(const nlohmann::json& json, EngineSpeed& speed) {
  speed = EngineSpeed{};
  speed.run = read_run(json);
  speed.mesh = json.value("mesh", "");
  speed.triangles = optional_number(json.value("triangles", nlohmann::json()));
  for (const auto& row : json.at("rows")) speed.rows.push_back(speed_row_from(row));
  if (json.contains("history") && json["history"].is_object()) speed.history = history_from(json["history"]);
}

}  // namespace affinterp::measurements
