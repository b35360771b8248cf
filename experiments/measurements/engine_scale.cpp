#include "experiments/measurements/engine_scale.hpp"

#include "experiments/bench/power_law.hpp"
#include "experiments/claims/speed_verdict.hpp"
#include "experiments/measurements/engine_scale_fields.hpp"
#include "experiments/measurements/scale_curve.hpp"
#include "experiments/measurements/scale_targets.hpp"
#include "theory/global/sparse_factor.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <map>
#include <utility>

namespace affinterp::measurements {
namespace {

using bench::BenchResults;

/// The exponents are fitted from this size up: below it fixed costs (threads, allocation) bend the curves.
constexpr double fit_from_triangles = 60'000;
/// Frames per batch_frames iteration (bench_scale.cpp).
constexpr double batch_frames = 8;

/// A benchmark of bench_scale, "kind/energy/triangles[/back-end]": scale_setup, scale_frame and batch_frames time
/// the engine as it chooses its back-end; backend_setup, backend_frame, backend_factor and backend_solve time one
/// back-end alone.
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

/// The least and the largest of a benchmark's runs (every repetition of every process) times `scale`; nullopt
/// with fewer than two runs (a file holding only aggregates).
std::optional<Interval> runs_spread(const std::optional<BenchResults>& results, const std::string& name, double scale) {
  if (!results) return std::nullopt;
  const auto it = results->repetitions.find(name);
  if (it == results->repetitions.end()) return std::nullopt;
  const std::vector<double> runs = bench::pooled(it->second);
  if (runs.size() < 2) return std::nullopt;
  const auto [least, largest] = std::minmax_element(runs.begin(), runs.end());
  return Interval{*least * scale, *largest * scale};
}

/// The three counters bench_scale records of each benchmark.
struct Counters {
  BenchResults times;
  std::optional<BenchResults> cpu, peaks;
};

/// Whether a benchmark times the engine as it chooses its back-end (else one back-end alone).
bool times_the_engine(const std::string& kind) {
  return kind == "scale_setup" || kind == "scale_frame" || kind == "batch_frames";
}

/// The engine's cost a benchmark of `kind` (times_the_engine) and `energy` measures at its size.
Cost& engine_cost(ScaleRow& row, const std::string& kind, const std::string& energy) {
  const bool F = energy == "F";
  if (kind == "scale_setup") return F ? row.setup_F : row.setup_R;
  if (kind == "scale_frame") return F ? row.frame_F : row.frame_R;
  return F ? row.batch_F : row.batch_R;
}

/// The size's peak is its largest benchmark's: the largest median, and of the spreads the largest least and the
/// largest largest.
void raise_peak(Cost& peak, const Counters& c, const std::string& name) {
  if (const std::optional<double> p = c.peaks ? (*c.peaks)[name] : std::nullopt)
    peak.value = std::max(peak.value.value_or(0.0), *p);
  if (const std::optional<Interval> r = runs_spread(c.peaks, name, 1))
    peak.runs = peak.runs ? Interval{std::max(peak.runs->lo, r->lo), std::max(peak.runs->hi, r->hi)} : *r;
}

/// One engine benchmark into its size's row: a batch's times per frame (amortised over its 8), a single frame's
/// and a set-up's with the calling thread's CPU time.
void add_engine_benchmark(ScaleRow& row, const BenchName& b, const std::string& name, const Counters& c) {
  const bool batch = b.kind == "batch_frames";
  const double per = batch ? 1 / batch_frames : 1;
  Cost& cost = engine_cost(row, b.kind, b.energy);
  cost.value = c.times.median.at(name) * per;
  cost.runs = runs_spread(c.times, name, per);
  if (!batch && c.cpu) cost.cpu_ms = (*c.cpu)[name];
  raise_peak(row.peak_MB, c, name);
}

/// One back-end benchmark (backend_<part>/E/size/<back-end>) into the back-end's row at its size.
void add_back_end_benchmark(BackEndRow& row, const BenchName& b, const std::string& name, const Counters& c) {
  const std::string key = b.kind.substr(8) + "_" + b.energy + "_ms";
  for (const BackEndField& f : back_end_fields)
    if (key == f.value_key) {
      (row.*f.cost).value = c.times.median.at(name);
      if (c.cpu) (row.*f.cost).cpu_ms = (*c.cpu)[name];
    }
}

/// The exponent of one cost over `rows`, from fit_from_triangles up (nullopt when undetermined).
template <class Row>
std::optional<double> exponent(const std::vector<Row>& rows, Cost Row::*cost) {
  std::vector<std::pair<double, double>> points;
  for (const Row& row : rows)
    if ((row.*cost).value) points.emplace_back(row.triangles, *(row.*cost).value);
  const double p = bench::power_law_exponent(points, fit_from_triangles);
  return std::isfinite(p) ? std::optional(p) : std::nullopt;
}

template <class Exponents, class Row, class Field, std::size_t N>
Exponents exponents_of(const std::vector<Row>& rows, const std::array<Field, N>& fields) {
  Exponents exponents;
  for (const Field& f : fields)
    if (f.exponent) exponents.*f.exponent = exponent(rows, f.cost);
  return exponents;
}

template <class Row>
std::vector<Row> ascending(const std::map<double, Row>& by_size) {
  std::vector<Row> rows;
  for (const auto& [triangles, row] : by_size) rows.push_back(row);
  return rows;
}

/// The engine's rows and each back-end's from every benchmark of the run.
void read_rows(const Counters& c, EngineScale& scale) {
  std::map<double, ScaleRow> engine;
  std::map<std::string, std::map<double, BackEndRow>> by_back_end;
  for (const auto& [name, ms] : c.times.median) {
    const std::optional<BenchName> b = parse(name);
    if (!b) continue;
    if (times_the_engine(b->kind)) {
      ScaleRow& row = engine[b->triangles];
      row.triangles = b->triangles;
      add_engine_benchmark(row, *b, name, c);
    } else if (b->kind.starts_with("backend_") && !b->back_end.empty()) {
      BackEndRow& row = by_back_end[b->back_end][b->triangles];
      row.triangles = b->triangles;
      add_back_end_benchmark(row, *b, name, c);
    }
  }
  scale.rows = ascending(engine);
  scale.exponents = exponents_of<ScaleExponents>(scale.rows, engine_fields);
  for (const auto& [name, sizes] : by_back_end) {
    std::vector<BackEndRow> rows = ascending(sizes);
    scale.back_ends.push_back({name, rows, exponents_of<BackEndExponents>(rows, back_end_fields)});
  }
}

}  // namespace

std::optional<EngineScale> engine_scale(const std::filesystem::path& bench_file, const claims::RunSettings& settings) {
  std::optional<BenchResults> times = bench::read_bench_results(bench_file, "real_time");
  if (!times) return std::nullopt;
  const Counters counters{std::move(*times), bench::read_bench_results(bench_file, "cpu_time"),
                          bench::read_bench_results(bench_file, "peak_MB")};
  EngineScale scale;
  scale.run = bench_run(counters.times);
  scale.blas = counters.times.context.value("affinterp_blas", "unknown");
  if (global::has_cholmod())
    scale.cholmod_from_unknowns =
        CholmodSwitch{global::cholmod_from_unknowns<double>, global::cholmod_from_unknowns<std::complex<double>>};
  read_rows(counters, scale);
  scale.exponents_from_triangles = fit_from_triangles;
  scale.targets = scale_targets();
  decide_targets(scale);
  if (settings.draws_figures() && !scale.rows.empty()) scale.figures = draw_cost_curve(settings, scale);
  return scale;
}

}  // namespace affinterp::measurements
