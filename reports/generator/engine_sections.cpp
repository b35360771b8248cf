#include "reports/generator/engine_sections.hpp"

#include "reports/generator/markdown.hpp"

#include <string>
#include <utility>

namespace affinterp::report {
namespace {

using measurements::Interval;
using measurements::Verdict;

/// A figure with its interval in brackets, when it has one.
std::string with_ci(const std::optional<double>& value, const std::optional<Interval>& ci, int digits) {
  return fixed(value, digits) + (ci ? " (" + fixed(ci->lo, digits) + "–" + fixed(ci->hi, digits) + ")" : "");
}

/// Where one frame's time goes (bench_interp's frame_rhs, frame_assembly, frame_factor and frame_solve medians),
/// or — without those rows.
std::string frame_parts_cell(const std::optional<measurements::FrameParts>& parts) {
  if (!parts) return "—";
  std::string cell;
  for (const auto& [ms, name] : {std::pair{parts->factor_ms, "numeric factorisation"},
                                 {parts->assembly_ms, "assembly of H(t)"},
                                 {parts->right_hand_side_ms, "right-hand side"},
                                 {std::optional(parts->solve_ms), "solve"}})
    if (ms) cell += (cell.empty() ? "" : ", ") + std::string(name) + " " + fixed(ms, 1) + " ms";
  cell += " on " + fixed(parts->threads, 0) + " threads; ";
  // The parts are benchmarks of their own, timed in other minutes than the frame: on a noisy machine they can sum
  // past the frame's median, which a negative "rest" would hide.
  if (parts->rest_ms < 0)
    return cell + "timed apart, the parts sum " + fixed(-parts->rest_ms, 1) + " ms past the frame's median";
  return cell + "the rest " + fixed(parts->rest_ms, 1) + " ms";
}

void write_speed_targets(std::ostringstream& md, const measurements::EngineSpeed& speed) {
  md << "The latest run: `build/bin/bench_interp` on " << (speed.mesh.empty() ? "?" : speed.mesh) << " ("
     << fixed(speed.triangles, 0)
     << " triangles), one frame at a time (each on the engine's own threads: from 8192 unknowns a frame's numeric "
        "factorisation and solve run their two groups of subtrees side by side) or in batches, the median of ten "
        "repetitions of at least a second each in each of the run's whole processes, with its 95% bootstrap "
        "interval over processes and repetitions (10,000 resamples, seed 2015; experiments/bench/measured.hpp): a "
        "target is met when the whole interval meets it, missed when none of it does, and undecided otherwise; "
     << measured_on(speed.run) << "; " << cell(speed.run.compiler)
     << ". Targets: E^F ≥ 150 frames/s, E^R ≥ 25 frames/s after set-up, set-up ≤ 200 ms. Each frame is solved as "
        "the n × n complex Hermitian system equivalent to the 2n × 2n real one (every energy commutes with turning "
        "all vertices by π/2; theory/global/hermitian_form.hpp): E^F's matrix is factored once, the others are "
        "refactorised every frame on a pattern analysed once. The baseline analyses and factorises the real 2n × 2n "
        "matrix from scratch every frame (its assembly untimed), as common public implementations do.\n\n"
     << "| energy | set-up (ms) | per frame (ms) | frames/s (95% CI) | target frames/s | baseline per frame (ms) | "
        "× baseline | targets met |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : speed.rows)
    md << "| " << row.energy << " | " << fixed(row.setup_ms, 1) << " | " << fixed(row.frame_ms, 2) << " | "
       << with_ci(row.frames_per_s.value, row.frames_per_s.ci95, 1) << " | " << fixed(row.target_frames_per_s, 0)
       << " | " << fixed(row.baseline_ms, 1) << " | " << fixed(row.speedup_vs_baseline, 1) << " | "
       << met_cell(row.verdict) << " |\n";
}

void write_raised_targets(std::ostringstream& md, const measurements::EngineSpeed& speed) {
  md << "\nThe raised targets are E^F ≥ 300 and E^R ≥ 60 frames/s, one frame at a time or in batches of 8 frames "
        "solved in parallel on the machine's cores (`batch_frames`, each worker factorising two E^R frames in one "
        "pass on the simplicial back-end: SparseFactor::factorise_two; the same interval rule):\n\n"
        "| energy | target frames/s | one at a time (95% CI) | met | batched (95% CI) | met | where a frame's time "
        "goes |\n|---|---|---|---|---|---|---|\n";
  for (const auto& row : speed.rows) {
    if (!row.raised_target_frames_per_s) continue;
    md << "| " << row.energy << " | " << fixed(row.raised_target_frames_per_s, 0) << " | "
       << with_ci(row.frames_per_s.value, row.frames_per_s.ci95, 1) << " | " << met_cell(row.raised_verdict) << " | "
       << with_ci(row.batched_frames_per_s, row.batched_frames_per_s_ci95, 1) << " | "
       << met_cell(row.raised_verdict_batched) << " | " << frame_parts_cell(row.frame_parts) << " |\n";
  }
  md << "\n";
}

void write_speed_runs(std::ostringstream& md, const measurements::SpeedHistory& history) {
  md << "Every recorded run (`bench/history/`), each decided alone:\n\n"
     << "| run | CPU | cores | energy | frames/s (95% CI) | set-up ms (95% CI) | processes | targets met |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : history.rows)
    md << "| " << row.run << (row.recorded ? "" : " (not recorded yet)") << " | " << cell(row.cpu) << " | "
       << (row.cores ? std::to_string(*row.cores) : "null") << " | " << row.energy << " | "
       << with_ci(row.frames_per_s.value, row.frames_per_s.ci95, 1) << " | "
       << (row.setup_ms ? with_ci(row.setup_ms->value, row.setup_ms->ci95, 1) : "—") << " | "
       << row.frames_per_s.processes << " | " << claims::to_string(row.verdict) << " |\n";
}

void write_speed_history(std::ostringstream& md, const measurements::SpeedHistory& history) {
  md << "Each machine's runs pooled (" << cell(history.rule) << "):\n\n"
     << "| machine | runs | energy | frames/s (95% CI) | set-up ms (95% CI) | targets met |\n"
        "|---|---|---|---|---|---|\n";
  for (const auto& row : history.machines)
    md << "| " << cell(row.machine) << " | " << row.runs << " | " << row.energy << " | "
       << with_ci(row.frames_per_s.value, row.frames_per_s.ci95, 1) << " | "
       << (row.setup_ms ? with_ci(row.setup_ms->value, row.setup_ms->ci95, 1) : "—") << " | "
       << claims::to_string(row.verdict) << " |\n";
  md << "\nAcross machines:";
  for (const auto& [energy, verdict] : history.across_machines)
    md << " E^" << energy << " " << claims::to_string(verdict) << ";";
  md << "\n\n";
  write_speed_runs(md, history);
  md << "\n";
}

}  // namespace

std::string measured_on(const measurements::BenchRun& run) {
  std::string date = run.date.empty() ? "date not recorded" : run.date;
  if (date.size() > 10 && date[10] == 'T') date[10] = ' ';
  return "measured on " + cell(run.machine.empty() ? "?" : run.machine) + ", " + date;
}

std::string met_cell(const std::optional<Verdict>& verdict) {
  if (!verdict) return "—";
  return *verdict == Verdict::reproduced ? "yes" : *verdict == Verdict::not_reproduced ? "**no**" : "undecided";
}

void write_engine_speed(std::ostringstream& md, const std::optional<measurements::EngineSpeed>& speed) {
  md << "## Global engine speed\n\n";
  if (!speed) {
    md << "Not measured: `reports/bench/bench_interp.json` is absent (run `experiments/reproduce.sh`).\n\n";
    return;
  }
  write_speed_targets(md, *speed);
  write_raised_targets(md, *speed);
  if (speed->history && !speed->history->rows.empty()) write_speed_history(md, *speed->history);
}

void write_engine_cli(std::ostringstream& md, const std::optional<measurements::EngineCli>& cli) {
  md << "### Through the CLI\n\n";
  if (!cli) {
    md << "Not measured: `reports/bench/bench_cli_scale.json` is absent (run `experiments/reproduce.sh --scale`).\n\n";
    return;
  }
  md << "`build/bin/bench_cli_scale`, " << measured_on(cli->run)
     << ": `affinterp interpolate --format npy --no-figures --metrics none` on "
        "`affinterp shapes strip-spiral --quads 2000x250` ("
     << fixed(cli->triangles, 0)
     << " triangles, a strip 18.8 × 2 rolled 1.5 turns), run as a process for 2 frames and for the table's extra "
        "frames more: a frame through the CLI, writing included, is the difference over the extra frames; the "
        "engine's frame is `vertices_at(times)` of 8 frames on the same pair, per frame, in the benchmark's own "
        "process (glibc's default allocator; the CLI keeps freed arrays in its heap, "
        "`experiments/apps/cli/main.cpp`). Medians of the repetitions, the ratio with its 95% bootstrap interval. "
        "Target: the CLI within "
     << fixed(cli->target_ratio, 1)
     << "× the engine (met when the interval lies at or below it): " << met_cell(cli->verdict)
     << ". The CLI's frames written into memory (`/dev/shm`) instead of the temporary folder's file system show "
        "what writing them costs there.\n\n"
        "| energy | extra frames | CLI frame (ms) | engine frame (ms) | CLI / engine | repetitions | met | CLI frame "
        "into memory (ms) | into memory / engine |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : cli->rows)
    md << "| E^" << row.energy << " | " << fixed(row.extra_frames, 0) << " | " << fixed(row.cli_frame_ms, 1) << " | "
       << fixed(row.engine_frame_ms, 1) << " | " << with_ci(row.ratio.value, row.ratio.ci95, 2) << " | "
       << row.ratio.repetitions << " | " << met_cell(row.verdict) << " | " << fixed(row.cli_memory_frame_ms, 1) << " | "
       << with_ci(row.memory_ratio, row.memory_ratio_ci95, 2) << " |\n";
  md << "\n";
}

}  // namespace affinterp::report
