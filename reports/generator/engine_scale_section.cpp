// The engine's cost against mesh size on the summary page (engine_sections.hpp's write_engine_scale).
#include "reports/generator/engine_sections.hpp"
#include "reports/generator/markdown.hpp"

#include <array>
#include <string>
#include <utility>

namespace affinterp::report {
namespace {

using measurements::BackEndRow;
using measurements::Cost;
using measurements::EngineScale;

void write_scale_intro(std::ostringstream& md, const EngineScale& scale) {
  const auto& switches = scale.cholmod_from_unknowns;
  md << "`build/bin/bench_scale`, " << measured_on(scale.run)
     << ", on the generated man bent by a curl through one radian, meshed from 1k to 65k triangles and the 65k pair "
        "subdivided 1-to-4 once and twice (261k, 1M), with `affinterp interpolate`'s default options; the median "
        "of five runs for the engine's rows (three for each back-end's). Wall-clock times, the calling thread's CPU "
        "time in brackets; a batched frame is `vertices_at(times)` of 8 frames on the machine's cores, per frame; "
        "peak memory is the process's resident high-water mark over each size's benchmarks. The sparse back-end is "
        "the project's simplicial up-looking LDLᴴ (AMD order, postordered) below "
     << fixed(switches ? std::optional<double>(switches->real) : std::nullopt, 0)
     << " unknowns (vertices) for E^F's real system, factored once, and below "
     << fixed(switches ? std::optional<double>(switches->complex) : std::nullopt, 0)
     << " for the complex systems refactorised every frame, CHOLMOD's supernodal LLᴴ from there: the switches set "
        "from the back-ends' factorisations and solves below; CHOLMOD's BLAS: "
     << cell(scale.blas)
     << ", on one thread (the engine runs frames in parallel itself). Reusing an earlier frame's factor to "
        "precondition conjugate gradients on E^R's frames was implemented and measured against refactorising "
        "(commit 33008f4): 4–6× slower on a gentle and two hard workloads at 250k triangles, so every E^R frame is "
        "factorised. Compiler: "
     << cell(scale.run.compiler) << ". ";
}

void write_scale_targets(std::ostringstream& md, const EngineScale& scale) {
  const measurements::ScaleTargets& t = scale.targets;
  md << "Targets at " << fixed(t.triangles, 0) << " triangles: set-up ≤ " << fixed(t.setup_ms, 0) << " ms, E^F ≤ "
     << fixed(t.frame_F_ms, 0) << " ms a frame, E^R ≤ " << fixed(t.batch_R_ms, 0)
     << " ms a batched frame growing at most " << fixed(t.growth_R, 0) << "× from the size before, peak ≤ "
     << fixed(t.peak_MB, 0)
     << " MB. A target is met when every run meets it, missed when none does, undecided otherwise (with five runs "
        "their least and largest bracket the median of runs with probability 94%, whatever the runs' "
        "distribution; a growth's runs are every pairing of the two sizes'): "
     << (scale.verdict ? "targets met: " + met_cell(scale.verdict) : std::string("not measured at that size"))
     << " (E^R's batched frame grew " << fixed(scale.growth_R, 1) << "× into the largest size).\n\n";
  if (scale.target_verdicts.empty()) return;
  md << "| target at " << fixed(t.triangles, 0)
     << " triangles | limit | median | runs (least–largest) | met | where the time goes (when not met) |\n"
        "|---|---|---|---|---|---|\n";
  for (const auto& v : scale.target_verdicts)
    md << "| " << cell(v.target) << " | " << fixed(v.limit, 1) << " | " << fixed(v.measured, 1) << " | "
       << (v.range ? fixed(v.range->lo, 1) + "–" + fixed(v.range->hi, 1) : std::string("—")) << " | "
       << met_cell(v.verdict) << " | " << cell(v.cause.value_or("—")) << " |\n";
  md << "\n";
}

/// A cost's wall-clock time with the calling thread's CPU time in brackets.
std::string both(const Cost& cost, int digits) {
  return fixed(cost.value, digits) + " (" + fixed(cost.cpu_ms, digits) + ")";
}

void write_scale_rows(std::ostringstream& md, const EngineScale& scale) {
  md << "| triangles | set-up E^F (ms) | set-up E^R (ms) | frame E^F (ms) | frame E^R (ms) | batched frame E^R (ms) "
        "| peak (MB) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& row : scale.rows)
    md << "| " << fixed(row.triangles, 0) << " | " << both(row.setup_F, 0) << " | " << both(row.setup_R, 0) << " | "
       << both(row.frame_F, 1) << " | " << both(row.frame_R, 1) << " | " << fixed(row.batch_R.value, 1) << " | "
       << fixed(row.peak_MB.value, 0) << " |\n";
  const measurements::ScaleExponents& p = scale.exponents;
  md << "| exponent p (cost ∝ n^p, from " << fixed(scale.exponents_from_triangles, 0) << ") | " << fixed(p.setup_F, 2)
     << " | " << fixed(p.setup_R, 2) << " | " << fixed(p.frame_F, 2) << " | " << fixed(p.frame_R, 2) << " | "
     << fixed(p.batch_R, 2) << " | " << fixed(p.peak_MB, 2) << " |\n\n";
}

/// The back-ends' table's columns: each cost of a back-end's row and its exponent.
constexpr std::array<std::pair<Cost BackEndRow::*, std::optional<double> measurements::BackEndExponents::*>, 8>
    back_end_columns{{{&BackEndRow::factor_F, &measurements::BackEndExponents::factor_F},
                      {&BackEndRow::factor_R, &measurements::BackEndExponents::factor_R},
                      {&BackEndRow::solve_F, &measurements::BackEndExponents::solve_F},
                      {&BackEndRow::solve_R, &measurements::BackEndExponents::solve_R},
                      {&BackEndRow::setup_F, &measurements::BackEndExponents::setup_F},
                      {&BackEndRow::setup_R, &measurements::BackEndExponents::setup_R},
                      {&BackEndRow::frame_F, &measurements::BackEndExponents::frame_F},
                      {&BackEndRow::frame_R, &measurements::BackEndExponents::frame_R}}};

void write_back_ends(std::ostringstream& md, const EngineScale& scale) {
  if (scale.back_ends.empty()) return;
  md << "Each back-end on the same matrices (`backend_*`: E^F's real L with two right-hand sides, E^R's complex "
        "H(½) with one), CPU ms of the calling thread (a `backend_factor` or `backend_solve` runs on it alone; "
        "set-up and frames use the second core too, not counted here: the loops over triangles on large meshes, "
        "the simplicial factor's two groups of subtrees):\n\n| back-end | triangles | factor E^F | factor E^R | "
        "solve E^F | solve E^R | set-up E^F | set-up E^R | frame E^F | frame E^R |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& back_end : scale.back_ends) {
    for (const auto& row : back_end.rows) {
      md << "| " << back_end.name << " | " << fixed(row.triangles, 0);
      for (const auto& [cost, exponent] : back_end_columns) md << " | " << fixed((row.*cost).cpu_ms, 1);
      md << " |\n";
    }
    md << "| " << back_end.name << " | exponent p";
    for (const auto& [cost, exponent] : back_end_columns) md << " | " << fixed(back_end.exponents.*exponent, 2);
    md << " |\n";
  }
  md << "\n";
}

}  // namespace

void write_engine_scale(std::ostringstream& md, const std::optional<EngineScale>& scale) {
  md << "## Global engine at scale\n\n";
  if (!scale) {
    md << "Not measured: `reports/bench/bench_scale.json` is absent (run `experiments/reproduce.sh --scale`).\n\n";
    return;
  }
  write_scale_intro(md, *scale);
  write_scale_targets(md, *scale);
  write_scale_rows(md, *scale);
  write_back_ends(md, *scale);
  for (const auto& f : scale->figures)
    if (f.ends_with(".png")) md << "![cost against mesh size](" << f << ")\n\n";
}

}  // namespace affinterp::report
