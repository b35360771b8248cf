#include "experiments/claims/engine_scale.hpp"

#include "experiments/bench/bench_results.hpp"
#include "experiments/bench/power_law.hpp"
#include "experiments/claims/speed_verdict.hpp"
#include "plots/engine_scale_curve.hpp"
#include "theory/global/sparse_factor.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::claims {
namespace {

constexpr double target_triangles = 1e6, setup_target_ms = 3000, frame_F_target_ms = 100, batch_R_target_ms = 600,
                 peak_target_MB = 2048, growth_R_target = 5;
/// The exponents are fitted from this size up: below it fixed costs (threads, allocation) bend the curves.
constexpr double fit_from_triangles = 60'000;
/// Frames per batch_frames iteration (bench_scale.cpp).
constexpr double batch_frames = 8;

/// A target "at most `limit`" against the spread of its runs, [least, largest], by the speed tables' interval rule
/// (speed_verdict.hpp): reproduced (met) when every run meets it, not-reproduced (missed) when none does,
/// inconclusive otherwise or without a spread. With five i.i.d. runs the least and the largest bracket the median
/// of runs with probability 1 − 2 · 2⁻⁵ ≈ 94%, whatever their distribution (order statistics), so a verdict does
/// not flip with the machine's noise as one on the median alone does.
Verdict verdict_on_runs(const nlohmann::json& range, double limit) {
  return verdict_of(
      range.is_array() ? std::optional(Interval{range[0].get<double>(), range[1].get<double>()}) : std::nullopt,
      {-kUnbounded, limit});
}

/// The least and the largest of a benchmark's runs (every repetition of every process) times `scale`; null with
/// fewer than two runs (a file holding only aggregates).
nlohmann::json runs_spread(const bench::BenchResults& results, const std::string& name, double scale) {
  const auto it = results.repetitions.find(name);
  if (it == results.repetitions.end()) return nullptr;
  const std::vector<double> runs = bench::pooled(it->second);
  if (runs.size() < 2) return nullptr;
  const auto [least, largest] = std::minmax_element(runs.begin(), runs.end());
  return {*least * scale, *largest * scale};
}

/// The spread of a quotient a / b of two spreads: over every pairing of their runs.
nlohmann::json quotient_spread(const nlohmann::json& a, const nlohmann::json& b) {
  if (!a.is_array() || !b.is_array()) return nullptr;
  return {a[0].get<double>() / b[1].get<double>(), a[1].get<double>() / b[0].get<double>()};
}

/// Splits "kind/energy/triangles[/back-end]".
struct BenchName {
  std::string kind, energy, back_end;
  double triangles = 0;
};
std::optional<BenchName> parse(const std::string& name) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t slash = name.find('/', start);
    parts.push_back(name.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  if (parts.size() < 3 || parts[2].empty() || !std::isdigit(static_cast<unsigned char>(parts[2][0])))
    return std::nullopt;
  return BenchName{parts[0], parts[1], parts.size() > 3 ? parts[3] : "", std::stod(parts[2])};
}

/// The rows of `by_size` in ascending size, every key of `keys` present (null: not measured).
nlohmann::json rows_of(std::map<double, nlohmann::json>& by_size, const std::vector<std::string>& keys) {
  nlohmann::json rows = nlohmann::json::array();
  for (auto& [triangles, row] : by_size) {
    for (const std::string& key : keys)
      if (!row.contains(key)) row[key] = nullptr;
    rows.push_back(row);
  }
  return rows;
}

/// The exponent of `key` over `rows` from fit_from_triangles up (null when undetermined).
nlohmann::json exponent(const nlohmann::json& rows, const std::string& key) {
  std::vector<std::pair<double, double>> points;
  for (const auto& row : rows)
    if (row[key].is_number()) points.emplace_back(row["triangles"].get<double>(), row[key].get<double>());
  const double p = bench::power_law_exponent(points, fit_from_triangles);
  return std::isfinite(p) ? nlohmann::json(p) : nlohmann::json();
}

/// Time (ms) and memory (MB) against triangles, log-log (plots/engine_scale_curve.hpp): the engine as it
/// chooses, and each back-end's set-up and frames, each line titled with its fitted exponent.
std::vector<std::string> draw_cost_curve(const RunSettings& settings, const nlohmann::json& scale) {
  std::vector<plots::CostSeries> series;
  auto add = [&](const nlohmann::json& rows, const nlohmann::json& exponents, const std::string& key,
                 const std::string& title, int colour, int dash, bool memory) {
    plots::CostSeries s{title, {}, colour, dash, memory};
    for (const auto& row : rows)
      if (row[key].is_number()) s.points.push_back({row["triangles"].get<double>(), row[key].get<double>()});
    if (s.points.empty()) return;
    if (exponents[key].is_number()) {
      char fitted[32];
      std::snprintf(fitted, sizeof fitted, " (n^{%.2f})", exponents[key].get<double>());
      s.title += fitted;
    }
    series.push_back(std::move(s));
  };
  const std::vector<std::pair<std::string, std::string>> quantities = {{"setup_F_ms", "set-up E^F"},
                                                                       {"setup_R_ms", "set-up E^R"},
                                                                       {"frame_F_ms", "E^F frame"},
                                                                       {"frame_R_ms", "E^R frame"}};
  int dash = 2;
  for (const auto& back_end : scale["back_ends"]) {
    int colour = 1;
    for (const auto& [key, title] : quantities)
      add(back_end["rows"], back_end["exponents"], key, title + ", " + back_end["name"].get<std::string>(), colour++,
          dash, false);
    ++dash;
  }
  add(scale["rows"], scale["exponents"], "batch_R_ms", "E^R frame, batched (engine)", 4, 1, false);
  add(scale["rows"], scale["exponents"], "peak_MB", "peak memory, MB (engine, right axis)", 7, 1, true);
  return RunSettings::figure_refs(plots::draw_engine_scale(settings.figure_stem("engine-scale"), series,
                                                           {{setup_target_ms, "set-up target at 1M", false},
                                                            {batch_R_target_ms, "E^R batched frame target", false},
                                                            {frame_F_target_ms, "E^F frame target", false},
                                                            {peak_target_MB, "memory target", true}}));
}

std::string ms(const nlohmann::json& value) {
  if (!value.is_number()) return "?";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f ms", value.get<double>());
  return text;
}

std::string times(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f×", x);
  return text;
}

/// The back-end's row at `triangles` (null when it did not run there).
nlohmann::json back_end_row(const nlohmann::json& back_ends, const std::string& name, double triangles) {
  for (const auto& back_end : back_ends)
    if (back_end["name"] == name)
      for (const auto& row : back_end["rows"])
        if (row["triangles"].get<double>() == triangles) return row;
  return nullptr;
}

/// Each target alone at the largest size `r` of `rows` (≥ 1M triangles): what was measured (the median of runs),
/// the spread of the runs, the verdict on that spread and, when it is not met, where the time goes by the run's own
/// rows of `back_end` (the engine's at this size).
struct TargetVerdicts {
  nlohmann::json targets;  ///< one entry per target
  Verdict all;             ///< all_of their verdicts
};
TargetVerdicts target_verdicts(const nlohmann::json& rows, std::size_t r, const nlohmann::json& growth_R,
                               const nlohmann::json& back_ends, const std::string& back_end,
                               const nlohmann::json& back_end_exponents) {
  const nlohmann::json& row = rows[r];
  const nlohmann::json parts = back_end_row(back_ends, back_end, row["triangles"].get<double>());
  const auto part = [&](const char* key) {
    return parts.is_null() ? nlohmann::json() : parts.value(key, nlohmann::json());
  };
  nlohmann::json verdicts = nlohmann::json::array();
  std::vector<Verdict> each;
  const auto add = [&](const std::string& target, const nlohmann::json& measured, const nlohmann::json& range,
                       double limit, std::string cause) {
    const Verdict verdict = each.emplace_back(verdict_on_runs(range, limit));
    verdicts.push_back(
        {{"target", target},
         {"limit", limit},
         {"measured", measured},
         {"range", range},
         {"verdict", to_string(verdict)},
         {"cause", verdict == Verdict::reproduced ? nlohmann::json() : nlohmann::json(std::move(cause))}});
  };
  const auto range = [&](const std::string& key) { return row.value(key + "_range", nlohmann::json()); };
  for (const char* energy : {"F", "R"}) {
    const std::string e = energy;
    add("set-up E^" + e, row["setup_" + e + "_ms"], range("setup_" + e), setup_target_ms,
        "of its " + ms(row["setup_" + e + "_cpu_ms"]) +
            " of the calling thread's CPU, the first numeric "
            "factorisation takes " +
            ms(part(("factor_" + e + "_cpu_ms").c_str())) + " (" + back_end +
            "); the local maps, the rotation branches, the sparsity pattern and the ordering take the rest");
  }
  add("E^F frame", row["frame_F_ms"], range("frame_F"), frame_F_target_ms,
      "the solve with the factor (two right-hand sides) takes " + ms(part("solve_F_cpu_ms")) + " of it (" + back_end +
          "); the local paths and the right-hand side the rest");
  const double batch_gain = row["frame_R_ms"].is_number() && row["batch_R_ms"].is_number()
                                ? row["frame_R_ms"].get<double>() / row["batch_R_ms"].get<double>()
                                : std::nan("");
  add("E^R batched frame", row["batch_R_ms"], range("batch_R"), batch_R_target_ms,
      "every E^R frame is a numeric factorisation, " + ms(part("factor_R_cpu_ms")) + " on one thread (" + back_end +
          "); a batch of 8 on the machine's cores made a frame " + times(batch_gain) + " faster than one at a time");
  const nlohmann::json p = back_end_exponents.value("factor_R_ms", nlohmann::json());
  char exponent_text[32] = "?";
  if (p.is_number()) std::snprintf(exponent_text, sizeof exponent_text, "%.2f", p.get<double>());
  std::string growth_cause = "the factorisation alone grows as n^" + std::string(exponent_text) + " (" + back_end + ")";
  if (r > 0 && rows[r - 1]["frame_R_ms"].is_number() && rows[r - 1]["batch_R_ms"].is_number())
    growth_cause += ", and the batch's gain over single frames went from " +
                    times(rows[r - 1]["frame_R_ms"].get<double>() / rows[r - 1]["batch_R_ms"].get<double>()) + " to " +
                    times(batch_gain);
  if (global::has_cholmod())
    growth_cause += "; below " + std::to_string(global::cholmod_from_unknowns<std::complex<double>>) +
                    " unknowns the complex systems factorise on the simplicial LDLᴴ instead (sparse_factor.hpp)";
  add("E^R batched frame's growth from the size before", growth_R,
      r > 0 ? quotient_spread(range("batch_R"), rows[r - 1].value("batch_R_range", nlohmann::json())) : nullptr,
      growth_R_target, growth_cause);
  add("peak memory (MB)", row["peak_MB"], range("peak_MB"), peak_target_MB, "the factors and the frames' workspaces");
  return {verdicts, all_of(each)};
}

}  // namespace

nlohmann::json engine_scale(const std::filesystem::path& bench_file, const RunSettings& settings) {
  const std::optional<bench::BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return nullptr;
  const std::optional<bench::BenchResults> cpu = bench::read_bench_results(bench_file, "cpu_time");
  const std::optional<bench::BenchResults> peaks = bench::read_bench_results(bench_file, "peak_MB");
  std::map<double, nlohmann::json> engine;                              // scale_* and batch_frames, by size
  std::map<std::string, std::map<double, nlohmann::json>> by_back_end;  // backend_*, by back-end and size
  for (const auto& [name, ms] : times->median) {
    const std::optional<BenchName> b = parse(name);
    if (!b) continue;
    const auto value_in = [&name](const std::optional<bench::BenchResults>& results) {
      const std::optional<double> value = results ? (*results)[name] : std::nullopt;
      return value ? nlohmann::json(*value) : nlohmann::json();
    };
    const nlohmann::json cpu_ms = value_in(cpu), peak = value_in(peaks);
    if (b->kind == "scale_setup" || b->kind == "scale_frame" || b->kind == "batch_frames") {
      nlohmann::json& row = engine[b->triangles];
      row["triangles"] = b->triangles;
      const std::string key = b->kind == "batch_frames" ? "batch_" + b->energy : b->kind.substr(6) + "_" + b->energy;
      const double per = b->kind == "batch_frames" ? 1 / batch_frames : 1;  // batches: per frame, amortised
      row[key + "_ms"] = ms * per;
      row[key + "_range"] = runs_spread(*times, name, per);
      if (cpu_ms.is_number() && b->kind != "batch_frames") row[key + "_cpu_ms"] = cpu_ms;
      if (peak.is_number()) row["peak_MB"] = std::max(row.value("peak_MB", 0.0), peak.get<double>());
      // The size's peak is its largest benchmark's: its spread, the largest of each benchmark's least and largest.
      if (const nlohmann::json r = peaks ? runs_spread(*peaks, name, 1) : nullptr; r.is_array()) {
        nlohmann::json& peak_range = row["peak_MB_range"];
        peak_range = peak_range.is_array() ? nlohmann::json{std::max(peak_range[0].get<double>(), r[0].get<double>()),
                                                            std::max(peak_range[1].get<double>(), r[1].get<double>())}
                                           : r;
      }
    } else if (b->kind.starts_with("backend_") && !b->back_end.empty()) {
      nlohmann::json& row = by_back_end[b->back_end][b->triangles];
      row["triangles"] = b->triangles;
      const std::string key = b->kind.substr(8) + "_" + b->energy;
      row[key + "_ms"] = ms;
      if (cpu_ms.is_number()) row[key + "_cpu_ms"] = cpu_ms;
    }
  }
  nlohmann::json rows = rows_of(
      engine, {"setup_F_ms", "setup_R_ms", "frame_F_ms", "frame_R_ms", "setup_F_cpu_ms", "setup_R_cpu_ms",
               "frame_F_cpu_ms", "frame_R_cpu_ms", "batch_F_ms", "batch_R_ms", "peak_MB", "setup_F_range",
               "setup_R_range", "frame_F_range", "frame_R_range", "batch_F_range", "batch_R_range", "peak_MB_range"});
  nlohmann::json exponents;
  for (const char* key : {"setup_F_ms", "setup_R_ms", "frame_F_ms", "frame_R_ms", "batch_R_ms", "peak_MB"})
    exponents[key] = exponent(rows, key);
  nlohmann::json back_ends = nlohmann::json::array();
  for (auto& [name, sizes] : by_back_end) {
    const std::vector<std::string> keys = {"setup_F_ms",  "setup_R_ms",  "frame_F_ms", "frame_R_ms",
                                           "factor_F_ms", "factor_R_ms", "solve_F_ms", "solve_R_ms"};
    std::vector<std::string> with_cpu = keys;
    for (const std::string& key : keys) with_cpu.push_back(key.substr(0, key.size() - 3) + "_cpu_ms");
    nlohmann::json back_end_rows = rows_of(sizes, with_cpu), back_end_exponents;
    for (const std::string& key : keys) back_end_exponents[key] = exponent(back_end_rows, key);
    back_ends.push_back({{"name", name}, {"rows", back_end_rows}, {"exponents", back_end_exponents}});
  }
  // At 1M triangles (≥ 500k vertices) the engine factors on CHOLMOD when built with it: above both switches.
  const std::string engine_back_end = global::has_cholmod() ? "cholmod" : "simplicial";
  nlohmann::json engine_back_end_exponents = nlohmann::json::object();
  for (const auto& back_end : back_ends)
    if (back_end["name"] == engine_back_end) engine_back_end_exponents = back_end["exponents"];
  nlohmann::json verdict = nullptr, growth_R = nullptr, verdicts = nlohmann::json::array();
  for (std::size_t r = 0; r < rows.size(); ++r) {  // the largest size at or beyond the targets' 1M triangles
    const nlohmann::json& row = rows[r];
    if (r > 0 && rows[r - 1]["batch_R_ms"].is_number() && row["batch_R_ms"].is_number())
      growth_R = row["batch_R_ms"].get<double>() / rows[r - 1]["batch_R_ms"].get<double>();
    if (row["triangles"].get<double>() >= target_triangles) {
      const TargetVerdicts decided =
          target_verdicts(rows, r, growth_R, back_ends, engine_back_end, engine_back_end_exponents);
      verdicts = decided.targets;
      verdict = to_string(decided.all);
    }
  }
  nlohmann::json scale = {
      {"file", bench_file.filename().string()},
      {"machine", times->machine},
      {"compiler", times->compiler},
      {"flags", times->flags},
      {"blas", times->context.value("affinterp_blas", "unknown")},
      {"cholmod_from_unknowns", global::has_cholmod()
                                    ? nlohmann::json{{"real", global::cholmod_from_unknowns<double>},
                                                     {"complex", global::cholmod_from_unknowns<std::complex<double>>}}
                                    : nlohmann::json()},
      {"rows", rows},
      {"exponents", exponents},
      {"exponents_from_triangles", fit_from_triangles},
      {"growth_R", growth_R},
      {"back_ends", back_ends},
      {"targets",
       {{"triangles", target_triangles},
        {"setup_ms", setup_target_ms},
        {"frame_F_ms", frame_F_target_ms},
        {"batch_R_ms", batch_R_target_ms},
        {"peak_MB", peak_target_MB},
        {"growth_R", growth_R_target}}},
      {"verdict", verdict},
      {"target_verdicts", verdicts}};
  scale["figures"] = settings.draws_figures() && !rows.empty() ? nlohmann::json(draw_cost_curve(settings, scale))
                                                               : nlohmann::json::array();
  return scale;
}

}  // namespace affinterp::claims
