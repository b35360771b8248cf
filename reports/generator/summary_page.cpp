#include "reports/generator/summary_page.hpp"

#include "experiments/measurements/engine3_quality.hpp"
#include "experiments/measurements/engine3_scale.hpp"
#include "experiments/measurements/engine3_speed.hpp"
#include "reports/generator/claim_lines.hpp"
#include "reports/generator/engine_sections.hpp"
#include "reports/generator/legend.hpp"
#include "reports/generator/markdown.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace affinterp::report {
namespace {

using nlohmann::json;

/// A record of claims.json (null: not measured), read through its from_json.
template <class Record>
std::optional<Record> record(const json& doc, const char* key) {
  const json entry = doc.value(key, json());
  return entry.is_null() ? std::nullopt : std::optional(entry.get<Record>());
}

std::string counts_of(const std::vector<const json*>& claims) {
  std::map<std::string, int> counts;
  for (const json* c : claims) ++counts[(*c)["verdict"].get<std::string>()];
  std::string text;
  for (const auto& [verdict, n] : counts) text += (text.empty() ? "" : ", ") + verdict + " " + std::to_string(n);
  return text;
}

/// A figure and an interactive viewer of the claim, linked from its row.
std::string figure_link(const json& figures) {
  std::string link;
  for (const auto& f : figures) {
    const std::string path = f.get<std::string>();
    if (path.ends_with(".png") && link.empty()) link = "[figure](" + path + ")";
  }
  for (const auto& f : figures)
    if (is_viewer(f.get<std::string>()))
      link += (link.empty() ? "" : " · ") + ("[viewer](" + f.get<std::string>() + ")");
  return link;
}

void write_claims_table(std::ostringstream& md, const json& claims) {
  md << "## Claims\n\nEach ID links to the claim's page: its evidence, tables, proof and figures.\n\n"
        "| ID | claim | verdict | strength | evidence | figure |\n|---|---|---|---|---|---|\n";
  for (const auto& c : claims) {
    const std::string id = c["id"];
    md << "| [`" << id << "`](" << claim_page_path(id) << ") | " << cell(c["statement"]) << " | **"
       << c["verdict"].get<std::string>() << "** | " << strength_words(c) << " | "
       << cell(one_line_evidence(c["evidence"])) << " | " << figure_link(c["figures"]) << " |\n";
  }
  md << "\n";
}

/// One paragraph per group of claims (an area of the papers): its verdicts, then each finding that is not a
/// confirmation, linked to its claim's page.
void write_areas(std::ostringstream& md, const json& claims) {
  std::vector<std::pair<std::string, std::vector<const json*>>> groups;
  for (const auto& c : claims) {
    const std::string group = c.value("group", "");
    if (groups.empty() || groups.back().first != group) groups.push_back({group, {}});
    groups.back().second.push_back(&c);
  }
  md << "## Areas\n\n";
  for (const auto& [group, members] : groups) {
    std::vector<const json*> not_confirmed;
    for (const json* c : members)
      if ((*c)["verdict"] != "confirmed") not_confirmed.push_back(c);
    md << "### " << group << "\n\n"
       << members.size() << " claims: " << counts_of(members) << (not_confirmed.empty() ? "." : "; the others:")
       << "\n\n";
    for (const json* c : not_confirmed) {
      const std::string id = (*c)["id"];
      md << "- [`" << id << "`](" << claim_page_path(id) << ") **" << (*c)["verdict"].get<std::string>()
         << "**: " << cell((*c)["summary"].get<std::string>()) << "\n";
    }
    md << (not_confirmed.empty() ? "" : "\n");
  }
}

/// The engine's area: its targets' verdicts on each record's run, linked to its sections below.
void write_engine_area(std::ostringstream& md, const std::optional<measurements::EngineSpeed>& speed,
                       const std::optional<measurements::EngineScale>& scale,
                       const std::optional<measurements::EngineCli>& cli) {
  md << "### Global engine speed and scale\n\nMeasurements of the engine, not claims of the papers. ";
  if (speed) {
    md << "[Speed](#global-engine-speed) on " << (speed->mesh.empty() ? "?" : speed->mesh) << " ("
       << measured_on(speed->run) << "), targets met:";
    for (const auto& row : speed->rows) md << " E^" << row.energy << " " << met_cell(row.verdict) << ";";
    md << " ";
  }
  if (scale)
    md << "[at scale](#global-engine-at-scale) (" << measured_on(scale->run)
       << "), the 1M-triangle targets met: " << met_cell(scale->verdict) << "; ";
  if (cli)
    md << "[through the CLI](#through-the-cli) (" << measured_on(cli->run) << "), within "
       << fixed(cli->target_ratio, 1) << "× the engine: " << met_cell(cli->verdict) << ".";
  md << "\n\n";
}

/// Why E^R and E^S stay in the plane, and what their 3D counterpart costs: an as-rigid-as-possible step against a
/// frame, both on one thread, when the run has both rows.
void write_arap_note(std::ostringstream& md, const measurements::Engine3Speed& speed) {
  const auto median = [&](std::string_view benchmark) -> std::optional<double> {
    for (const auto& row : speed.rows)
      if (row.benchmark == benchmark) return row.median_ms;
    return std::nullopt;
  };
  const auto step = median("3d/arap-step"), frame = median("3d/frame-1-thread");
  md << "\nE^R and E^S stay in the plane: their closed form minimises over similarities written as complex numbers, "
        "and 3D similarities form no field, so the minimum over rotations (a Procrustes problem) is not a quadratic "
        "form in the vertices and no one-solve-per-frame counterpart exists (theory/global3/interpolation3.hpp). "
        "The nearest sound counterpart is offered instead: `arap_iterations` as-rigid-as-possible steps on each "
        "E^F frame (E^R with its scale held at 1; theory/global3/arap_refinement3.hpp)";
  if (step && frame)
    md << ", one step costing " << fixed(*step, 1) << " ms against " << fixed(*frame, 1) << " ms for a frame ("
       << fixed(*step / *frame, 1) << "×: a solve and a rotation fitted to each element)";
  md << ".\n";
}

/// The 3D engine's speed (bench_3d): each benchmark's median and the spread of its repetitions, the target and its
/// verdict where the row has one, and a frame's parts.
void write_engine3_speed(std::ostringstream& md, const std::optional<measurements::Engine3Speed>& speed) {
  if (!speed) return;
  md << "### 3D engine speed\n\nbench_3d on " << fixed(speed->triangles, 0) << " triangles (" << measured_on(speed->run)
     << "): the 3D engine (E^F, exp-log) on the cat of Sumner and Popović (2004) subdivided once, or CGAL's elephant "
        "subdivided twice without it. Measurements, not claims; a target (2 cores) is met when every repetition meets "
        "it, missed when none does.\n\n"
        "| benchmark | one iteration | median ms | least – largest ms | target | met |\n|---|---|---|---|---|---|\n";
  for (const auto& row : speed->rows) {
    md << "| `" << row.benchmark << "` | " << cell(row.what) << " | " << fixed(row.median_ms, 2) << " | "
       << fixed(row.range_ms.lo, 2) << " – " << fixed(row.range_ms.hi, 2) << " | ";
    if (row.limit_ms && row.verdict)
      md << "≤ " << fixed(*row.limit_ms, 0) << " ms | " << met_cell(*row.verdict) << " |\n";
    else
      md << " |  |\n";
  }
  if (speed->parts)
    md << "\nA frame's parts (one thread, medians): local maps with the symmetric exponential "
       << fixed(speed->parts->local_maps_ms, 2) << " ms, right-hand side " << fixed(speed->parts->right_hand_side_ms, 2)
       << " ms, solve " << fixed(speed->parts->solve_ms, 2) << " ms.\n";
  write_arap_note(md, *speed);
  md << "\n";
}

/// The 3D engine at a million triangles (bench_3d_scale, --scale only): each target with its median, spread and
/// verdict.
void write_engine3_scale(std::ostringstream& md, const std::optional<measurements::Engine3Scale>& scale) {
  if (!scale) return;
  const auto target = [&](const char* what, const measurements::Engine3Target& t, const char* unit, int digits) {
    md << "| " << what << " | " << fixed(t.median, digits) << " | " << fixed(t.range.lo, digits) << " – "
       << fixed(t.range.hi, digits) << " | ≤ " << fixed(t.limit, digits) << " " << unit << " | " << met_cell(t.verdict)
       << " |\n";
  };
  md << "At a million triangles: bench_3d_scale on CGAL's elephant subdivided four times, "
     << fixed(scale->triangles, 0) << " triangles, towards its twist (" << measured_on(scale->run)
     << "; `reproduce.sh --scale`), the set-up and a frame on two threads in wall time, peak resident memory. A target "
        "is met when every repetition meets it, missed when none does.\n\n"
        "| cost | median | least – largest | target | met |\n|---|---|---|---|---|\n";
  target("set-up (s)", scale->setup_s, "s", 2);
  target("frame, two threads (ms)", scale->frame_ms, "ms", 0);
  target("peak memory (MB)", scale->peak_MB, "MB", 0);
  md << "\n";
}

/// The 3D engine's frames against baselines (quality_3d): per method and pose pair, the most elements inverted in a
/// frame, and the middle frame's mean distortion.
void write_engine3_quality(std::ostringstream& md, const std::optional<measurements::Engine3Quality>& quality) {
  if (!quality) return;
  md << "### 3D frames against baselines\n\n"
        "quality_3d at "
     << quality->frames
     << " frames per pair (t = 0 … 1), the same numbers on every run: the most elements inverted in one frame "
        "(the first such frame's t), counted against the exp-log local maps A_i(t) on consistent branches for every "
        "method (a triangle whose normal opposes A_i(t) n_p), then the mean distortion σ1/σ2 of the frame at "
        "t = 1/2. E^F with the linear homotopy is the per-vertex linear blend exactly (the maps (1 − t)I + tA_i are "
        "fitted exactly by (1 − t)P + tQ). The first row counts the triangles the target pose itself folds within "
        "the surface (its normal opposes the source's carried by the rotation fitted to the triangle's vertex "
        "one-ring): each element map makes such a fold a half-turn about an axis in the surface, which the triangles "
        "sharing its vertices cannot follow rigidly, so frames may invert at or beside it; \"away\" counts, in the "
        "frame with the most, the inverted elements that are neither a fold nor share a vertex with one. The "
        "as-rigid-as-possible row lets every element turn its exp-log map on "
        "each frame (E^R's 3D counterpart with the scale held at 1: theory/global3/arap_refinement3.hpp) and is "
        "still counted against the unturned A_i(t). The cat poses are Sumner and Popović's (SIGGRAPH 2004). "
        "Measurements, not claims.\n\n| method |";
  for (std::size_t p = 0; p < quality->pairs.size(); ++p)
    md << " " << quality->pairs[p] << " (" << quality->elements[p] << ") |";
  md << " most in any pair |\n|---|";
  for (std::size_t p = 0; p <= quality->pairs.size(); ++p) md << "---|";
  md << "\n";
  if (!quality->target_folds.empty()) {
    md << "| target's folds (the input) |";
    for (const long folds : quality->target_folds) md << " " << folds << " |";
    md << " " << *std::max_element(quality->target_folds.begin(), quality->target_folds.end()) << " |\n";
  }
  for (std::size_t m = 0; m < quality->methods.size(); ++m) {
    md << "| " << cell(quality->methods[m]) << " |";
    long most = 0;
    for (const auto& c : quality->cells[m]) {
      most = std::max(most, c.most_inverted);
      md << " " << c.most_inverted;
      if (c.most_inverted > 0) md << " (t = " << fixed(c.at_t, 2) << "; away " << c.most_inverted_away << ")";
      md << ", " << fixed(c.middle_distortion, 2) << " |";
    }
    md << " " << most << " |\n";
  }
  md << "\n";
  if (const auto& c = quality->closeup) {
    md << "Up close, E^F exp-log's frame with the most inverted triangles away from its target's folds: " << c->pair
       << " at t = " << fixed(c->t, 2) << ", " << c->inverted << " inverted, " << c->inverted_away
       << " of them away from the folds; the piece of surface within " << measurements::closeup_rings
       << " vertex rings of triangle " << c->centre
       << " in the source, that frame and the target, each turned onto the source's piece (purple: the target's "
          "folds; orange: inverted at or beside one; red: inverted away from them).\n\n";
    for (const auto& f : quality->figures)
      if (f.ends_with(".png")) md << "![inverted triangles up close](" << f << ")\n\n";
  }
}

void write_environment(std::ostringstream& md, const json& doc) {
  md << "## How to reproduce\n\n"
        "From a fresh clone on Debian, `bash experiments/reproduce.sh` installs what is missing, builds, "
        "runs the benchmarks and writes this report, its claims' pages and `claims.json`. One claim alone: "
        "`build/bin/affinterp claims --only ID`; with another seed: `--seed N`; the pages again from `claims.json` "
        "without running any check: `build/bin/affinterp report`.\n\n"
        "## Environment\n\n| | |\n|---|---|\n";
  for (const auto& [key, value] : doc["environment"].items())
    md << "| " << key << " | " << cell(value.is_string() ? value.get<std::string>() : value.dump()) << " |\n";
  md << "| seed | " << doc.value("seed", 0ull) << " |\n";
}

}  // namespace

std::string render_summary_page(const json& doc) {
  const json& claims = doc["claims"];
  std::vector<const json*> all;
  for (const auto& c : claims) all.push_back(&c);
  const auto speed = record<measurements::EngineSpeed>(doc, "engine_speed");
  const auto scale = record<measurements::EngineScale>(doc, "engine_scale");
  const auto cli = record<measurements::EngineCli>(doc, "engine_cli");
  const auto engine3 = record<measurements::Engine3Speed>(doc, "engine3_speed");
  const auto quality3 = record<measurements::Engine3Quality>(doc, "engine3_quality");
  const auto scale3 = record<measurements::Engine3Scale>(doc, "engine3_scale");
  std::ostringstream md;
  md << "# affinterp report\n\n"
     << "Which claims of Kaji et al., *Mathematical Analysis on Affine Maps for 2D Shape Interpolation* "
        "(SCA 2012) and Matsushita, *A Study on 2D Shape Interpolation Using Affine Maps* (thesis, 2015) "
        "hold, decided by computations this suite runs itself.\n\n"
     << "Generated " << doc.value("generated_at", "") << " with seed " << doc.value("seed", 0ull) << ", size `"
     << doc.value("size", "") << "`. Verdicts: " << counts_of(all) << ".\n\n";
  write_claims_table(md, claims);
  write_areas(md, claims);
  write_engine_area(md, speed, scale, cli);
  write_engine3_speed(md, engine3);
  write_engine3_scale(md, scale3);
  write_engine3_quality(md, quality3);
  write_verdict_legend(md);
  write_strength_legend(md, claims);
  write_engine_speed(md, speed);
  write_engine_scale(md, scale);
  write_engine_cli(md, cli);
  write_environment(md, doc);
  return md.str();
}

}  // namespace affinterp::report
