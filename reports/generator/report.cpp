#include "reports/generator/report.hpp"

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace affinterp::report {

namespace {

using nlohmann::json;

/// Markdown table cells must not contain a bare '|' or a line break.
std::string cell(std::string text) {
  std::string out;
  for (const char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string anchor(const std::string& id) {
  std::string out;
  for (const char c : id)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-') out += c;
  return out;
}

std::string number(const json& value) {
  if (value.is_null()) return "";
  std::ostringstream out;
  out << value.get<double>();
  return out.str();
}

std::string one_line_evidence(const json& evidence) {
  std::ostringstream out;
  out << evidence.value("method", "");
  if (evidence.value("sample_size", 0ull) > 0) out << "; n = " << evidence["sample_size"].get<unsigned long long>();
  if (!evidence["seed"].is_null()) out << "; seed " << evidence["seed"].get<unsigned long long>();
  if (!evidence["tolerance"].is_null()) out << "; tol " << number(evidence["tolerance"]);
  if (!evidence["worst_deviation"].is_null()) out << "; worst " << number(evidence["worst_deviation"]);
  return out.str();
}

/// An interactive viewer page among a claim's figures (plots/viewer.hpp): linked, not shown as an image.
bool is_viewer(const std::string& path) { return path.ends_with(".html"); }

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

/// The checkers that answered every sentence of a formulation they ran on, "qepcad, z3".
std::string checkers(const json& proof) {
  std::string names;
  for (const auto& tool : proof.value("checked_by", json::array()))
    names += (names.empty() ? "" : ", ") + tool.get<std::string>();
  return names.empty() ? "none" : names;
}

/// How strong a claim's verdict is, in the words of the report's "Strength" list.
std::string strength_words(const json& claim) {
  const std::string strength = claim.value("strength", "unstated");
  const json proof = claim.value("proof", json());
  if (strength == "proved") return "proved for all reals";
  if (strength == "proved-one-decider") return "proved, one decider (" + checkers(proof) + ")";
  if (strength == "proved-citing") return "proved, citing " + proof.value("cites", std::string("?"));
  if (strength == "exact-counterexample") {
    if (!proof.is_object() || proof.value("checked_by", json::array()).size() < 2) return "exact counterexample";
    return "exact counterexample; rest proved (" + checkers(proof) + ")";
  }
  if (strength == "grid") return "grid only";
  if (strength == "sample") return "sample only";
  if (strength == "measured") return "measured";
  return "not stated";
}

/// A formulation's sentences with each checker's result and the files to rerun them with; whether one is
/// structural.
bool write_sentences(std::ostringstream& md, const json& proof) {
  md << "| sentence | meaning | result | each checker: its answer (transcript), the time it took |\n"
        "|---|---|---|---|\n";
  bool any_structural = false;
  for (const auto& s : proof["sentences"]) {
    std::string runs;
    for (const auto& r : s["runs"]) {
      // A decider's transcript is <sentence>.<tool>.out beside its input (experiments/proofs/transcript.hpp).
      const std::string tool = r.value("tool", ""), file = r.value("file", "");
      const bool decider = tool == "qepcad" || tool == "z3" || tool == "cvc5";
      std::ostringstream one;
      one.precision(2);
      one << std::fixed << "[" << tool << "](" << file << "): [" << r.value("result", "") << "](";
      if (decider)
        one << file.substr(0, file.rfind('/') + 1) << s.value("name", "") << "." << tool << ".out";
      else
        one << file;
      one << ") " << r.value("seconds", 0.0) << " s";
      runs += (runs.empty() ? "" : "; ") + one.str();
    }
    const bool structural = s.value("structural", false);
    any_structural = any_structural || structural;
    md << "| " << cell(s.value("name", "")) << " | " << cell(s.value("meaning", "")) << " | " << s.value("result", "")
       << (structural ? " (structural)" : "") << " | " << cell(runs) << " |\n";
  }
  return any_structural;
}

/// What was tried for the record (issue 17): the attempted formulations' runs, answered or not, and the
/// formulations' unanswered runs: formulation, tool, CPU time, peak memory, outcome.
void write_attempts(std::ostringstream& md, const json& attempts) {
  md << "**Tried for the record** (attempted formulations, each run with its outcome, and the runs that answered "
        "nothing; the label rests on the formulations above):\n\n"
        "| formulation | sentence | tool | CPU time | peak memory | outcome |\n|---|---|---|---|---|---|\n";
  for (const auto& a : attempts) {
    std::ostringstream cpu, memory;
    cpu.precision(1);
    cpu << std::fixed;
    if (a.value("cpu_seconds", json()).is_number())
      cpu << a["cpu_seconds"].get<double>() << " s";
    else
      cpu << "—";
    if (a.value("max_rss_kb", json()).is_number())
      memory << a["max_rss_kb"].get<long>() / 1024 << " MiB";
    else
      memory << "—";
    const std::string file = a.value("file", ""), tool = a.value("tool", "");
    md << "| " << cell(a.value("formulation", "")) << " | " << cell(a.value("sentence", "")) << " | "
       << (tool.empty()   ? "—"
           : file.empty() ? tool
                          : "[" + tool + "](" + file + ")")
       << " | " << cpu.str() << " | " << memory.str() << " | " << cell(a.value("outcome", "")) << " |\n";
  }
  md << "\n";
}

/// The sentences of a proof with each decider's result and the files to rerun them with; its further
/// formulations (issue 17) the same way; what was tried and not answered.
void write_proof(std::ostringstream& md, const json& proof) {
  md << "**Proof for all reals.** Scope: " << proof.value("scope", "") << ". Method: " << proof.value("method", "")
     << ". Decided by " << checkers(proof) << ".\n\n";
  bool any_structural = write_sentences(md, proof);
  int k = 1;
  for (const auto& f : proof.value("formulations", json::array())) {
    md << "\n**Formulation " << ++k << ".** Method: " << f.value("method", "") << ". Decided by " << checkers(f)
       << ".\n\n";
    any_structural = write_sentences(md, f) || any_structural;
  }
  if (any_structural)
    md << "\n*Structural*: empty for propositional reasons alone (every polynomial atom replaced by a boolean, "
          "the sentence stays unsatisfiable), so no evidence for the claim; its weight rests on the lemmas.\n";
  md << "\n";
  if (proof.contains("attempts")) write_attempts(md, proof["attempts"]);
}

void write_summary_table(std::ostringstream& md, const json& claims) {
  md << "| ID | claim | verdict | strength | evidence | figure |\n|---|---|---|---|---|---|\n";
  for (const auto& c : claims) {
    const std::string id = c["id"];
    md << "| [`" << id << "`](#" << anchor(id) << ") | " << cell(c["statement"]) << " | **"
       << c["verdict"].get<std::string>() << "** | " << strength_words(c) << " | "
       << cell(one_line_evidence(c["evidence"])) << " | " << figure_link(c["figures"]) << " |\n";
  }
}

/// A claim's tables (evidence.details.tables: [{"title", "columns": [...], "rows": [[cells]], "replaces": [keys of
/// details the table stands for in the report]}]) as Markdown.
void write_tables(std::ostringstream& md, const json& tables) {
  for (const auto& table : tables) {
    md << "**" << table.value("title", "") << "**\n\n|";
    for (const auto& column : table["columns"]) md << " " << cell(column.get<std::string>()) << " |";
    md << "\n|";
    for (std::size_t i = 0; i < table["columns"].size(); ++i) md << "---|";
    md << "\n";
    for (const auto& row : table["rows"]) {
      md << "|";
      for (const auto& entry : row)
        md << " " << cell(entry.is_string() ? entry.get<std::string>() : entry.dump()) << " |";
      md << "\n";
    }
    md << "\n";
  }
}

void write_claim_section(std::ostringstream& md, const json& c) {
  const std::string id = c["id"];
  md << "<a id=\"" << anchor(id) << "\"></a>\n### `" << id << "`: " << c["verdict"].get<std::string>() << "\n\n*"
     << c["where"].get<std::string>() << ".* " << c["statement"].get<std::string>() << "\n\n";
  if (!c["summary"].get<std::string>().empty()) md << "**Finding.** " << c["summary"].get<std::string>() << "\n\n";
  const json& e = c["evidence"];
  md << "**Evidence.** " << one_line_evidence(e) << ".\n\n";
  json details = e["details"];
  if (details.is_object() && details.contains("tables")) {
    write_tables(md, details["tables"]);
    // A table stands for the details it names under "replaces" (claims.json keeps them in full).
    for (const auto& table : details["tables"])
      for (const auto& key : table.value("replaces", json::array())) details.erase(key.get<std::string>());
    details.erase("tables");
  }
  if (!details.empty()) md << "```json\n" << details.dump(2) << "\n```\n\n";
  if (!e["measurements"].empty())
    md << "Measurements (vary run to run):\n\n```json\n" << e["measurements"].dump(2) << "\n```\n\n";
  if (!c["counterexample"].is_null())
    md << "**Counterexample** (exact values as \"p/q\"):\n\n```json\n" << c["counterexample"].dump(2) << "\n```\n\n";
  if (!c["correction"].is_null()) md << "**Correction.** " << c["correction"].get<std::string>() << "\n\n";
  if (c.contains("condition") && c["condition"].is_string())
    md << "**Condition** (in the `affinterp decide` grammar): `" << c["condition"].get<std::string>() << "`\n\n";
  if (c.contains("proof") && c["proof"].is_object()) write_proof(md, c["proof"]);
  for (const auto& f : c["figures"]) {
    const std::string path = f.get<std::string>();
    if (path.ends_with(".png")) md << "![" << id << "](" << path << ")\n\n";
  }
  for (const auto& f : c["figures"])
    if (is_viewer(f.get<std::string>()))
      md << "[Interactive viewer](" << f.get<std::string>()
         << "): scrub through the frames, colour the triangles by area ratio, distortion or flips, see the "
            "energy over time (open in a browser; it works offline).\n\n";
}

std::string fixed(const json& value, int digits) {
  if (value.is_null()) return "—";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value.get<double>();
  return out.str();
}

/// A figure with its 95% interval in brackets, when it has one.
std::string with_ci(const json& value, const json& ci, int digits) {
  return fixed(value, digits) +
         (ci.is_array() ? " (" + fixed(ci[0], digits) + "–" + fixed(ci[1], digits) + ")" : std::string());
}

/// A speed verdict as a table cell: met (reproduced), **no** (not-reproduced), undecided, or — when none.
std::string met_cell(const json& verdict) {
  if (!verdict.is_string()) return "—";
  const std::string v = verdict.get<std::string>();
  return v == "reproduced" ? "yes" : v == "not-reproduced" ? "**no**" : "undecided";
}

/// Where one frame's time goes (engine_speed.hpp's frame_parts: bench_interp's frame_rhs, frame_assembly,
/// frame_factor and frame_solve medians), or — without those rows.
std::string frame_parts_cell(const json& parts) {
  if (!parts.is_object()) return "—";
  std::string cell;
  for (const auto& [key, name] : {std::pair{"factor_ms", "numeric factorisation"},
                                  {"assembly_ms", "assembly of H(t)"},
                                  {"right_hand_side_ms", "right-hand side"},
                                  {"solve_ms", "solve"}})
    if (parts.value(key, json()).is_number())
      cell += (cell.empty() ? "" : ", ") + std::string(name) + " " + fixed(parts[key], 1) + " ms";
  cell += " on " + fixed(parts.value("threads", json()), 0) + " threads; ";
  // The parts are benchmarks of their own, timed in other minutes than the frame: on a noisy machine they can sum
  // past the frame's median, which a negative "rest" would hide.
  const json rest = parts.value("rest_ms", json());
  if (rest.is_number() && rest.get<double>() < 0)
    return cell + "timed apart, the parts sum " + fixed(-rest.get<double>(), 1) + " ms past the frame's median";
  return cell + "the rest " + fixed(rest, 1) + " ms";
}

/// The global engine's speed against its targets (bench_interp, one run on one machine).
void write_engine_speed(std::ostringstream& md, const json& speed) {
  md << "## Global engine speed\n\n";
  if (speed.is_null()) {
    md << "Not measured: `reports/bench/bench_interp.json` is absent (run `experiments/reproduce.sh`).\n\n";
    return;
  }
  md << "The latest run: `build/bin/bench_interp` on " << speed.value("mesh", "?") << " ("
     << fixed(speed.value("triangles", json()), 0)
     << " triangles), one frame at a time (each on the engine's own threads: from 8192 unknowns a frame's numeric "
        "factorisation and solve run their two groups of subtrees side by side) or in batches, the median of ten "
        "repetitions of at least a second each in each of the run's "
        "whole processes, with its 95% bootstrap interval over processes and repetitions (10,000 resamples, seed "
        "2015; experiments/bench/measured.hpp): a target is met when the whole "
        "interval meets it, missed when none of it does, and undecided otherwise; machine: "
     << cell(speed.value("machine", "?")) << "; " << cell(speed.value("compiler", "?"))
     << ". Targets: E^F ≥ 150 frames/s, E^R ≥ 25 frames/s after set-up, "
        "set-up ≤ 200 ms. Each frame is solved as the n × n complex Hermitian system equivalent to the 2n × 2n "
        "real one (every energy commutes with turning all vertices by π/2; theory/global/hermitian_form.hpp): "
        "E^F's matrix is factored once, the others are refactorised every frame on a pattern analysed once. "
        "The baseline analyses and factorises the real 2n × 2n matrix from scratch every frame (its assembly "
        "untimed), as common public implementations do.\n\n"
     << "| energy | set-up (ms) | per frame (ms) | frames/s (95% CI) | target frames/s | baseline per frame (ms) | "
        "× baseline | targets met |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : speed["rows"])
    md << "| " << row.value("energy", "") << " | " << fixed(row["setup_ms"], 1) << " | " << fixed(row["frame_ms"], 2)
       << " | " << with_ci(row["frames_per_s"], row.value("frames_per_s_ci95", json()), 1) << " | "
       << fixed(row["target_frames_per_s"], 0) << " | " << fixed(row["baseline_ms"], 1) << " | "
       << fixed(row["speedup_vs_baseline"], 1) << " | " << met_cell(row.value("verdict", "inconclusive")) << " |\n";
  md << "\nIssue 19 raises the targets to E^F ≥ 300 and E^R ≥ 60 frames/s, one frame at a time or in batches of 8 "
        "frames solved in parallel on the machine's cores (`batch_frames`, each worker factorising two E^R frames in "
        "one pass on the simplicial back-end: SparseFactor::factorise_two; the same interval rule):\n\n"
        "| energy | target frames/s | one at a time (95% CI) | met | batched (95% CI) | met | where a frame's time "
        "goes |\n|---|---|---|---|---|---|---|\n";
  for (const auto& row : speed["rows"]) {
    if (!row.value("raised_target_frames_per_s", json()).is_number()) continue;
    md << "| " << row.value("energy", "") << " | " << fixed(row["raised_target_frames_per_s"], 0) << " | "
       << with_ci(row["frames_per_s"], row.value("frames_per_s_ci95", json()), 1) << " | "
       << met_cell(row.value("raised_verdict", json())) << " | "
       << with_ci(row.value("batched_frames_per_s", json()), row.value("batched_frames_per_s_ci95", json()), 1) << " | "
       << met_cell(row.value("raised_verdict_batched", json())) << " | "
       << frame_parts_cell(row.value("frame_parts", json())) << " |\n";
  }
  md << "\n";
  const json history = speed.value("history", json());
  if (!history.is_object() || history["rows"].empty()) return;
  md << "On every recorded run (`bench/history/`; " << cell(history.value("rule", "")) << "):\n\n"
     << "| run | CPU | cores | energy | frames/s (95% CI) | set-up ms (95% CI) | processes | targets met |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : history["rows"])
    md << "| " << row.value("run", "") << (row.value("recorded", true) ? "" : " (not recorded yet)") << " | "
       << cell(row["cpu"].is_string() ? row["cpu"].get<std::string>() : "?") << " | " << row["cores"].dump() << " | "
       << row.value("energy", "") << " | " << with_ci(row["frames_per_s"], row["frames_per_s_ci95"], 1) << " | "
       << with_ci(row["setup_ms"], row["setup_ms_ci95"], 1) << " | " << row["processes"].dump() << " | "
       << row.value("verdict", "") << " |\n";
  md << "\nAcross runs:";
  for (const auto& [energy, verdict] : history["across_runs"].items())
    md << " E^" << energy << " " << verdict.get<std::string>() << ";";
  md << "\n\n";
}

/// How the engine's cost grows with the mesh against the 1M-triangle targets (bench_scale, one run), and each
/// sparse back-end's factorisation and solve side by side.
void write_engine_scale(std::ostringstream& md, const json& scale) {
  md << "## Global engine at scale\n\n";
  if (scale.is_null()) {
    md << "Not measured: `reports/bench/bench_scale.json` is absent (run `experiments/reproduce.sh`).\n\n";
    return;
  }
  const json targets = scale.value("targets", json::object());
  const auto target = [&](const char* key) { return targets.value(key, json()); };
  const json switches = scale.value("cholmod_from_unknowns", json());
  const auto switch_at = [&](const char* scalar) {
    return switches.is_object() ? switches.value(scalar, json()) : json();
  };
  md << "`build/bin/bench_scale` on the generated man bent by a curl through one radian, meshed from 1k to 65k "
        "triangles and the 65k pair subdivided 1-to-4 once and twice (261k, 1M), with `affinterp interpolate`'s "
        "default options; the median of five runs for the engine's rows (three for each back-end's). Wall-clock "
        "times, the calling thread's CPU time in brackets; "
        "a batched frame is `vertices_at(times)` of 8 frames on the machine's cores, per frame; peak memory is the "
        "process's resident high-water mark over each size's benchmarks. The sparse back-end is the project's "
        "simplicial "
        "up-looking LDLᴴ (AMD order, postordered) below "
     << fixed(switch_at("real"), 0) << " unknowns (vertices) for E^F's real system, factored once, and below "
     << fixed(switch_at("complex"), 0)
     << " for the complex systems refactorised every frame, CHOLMOD's supernodal LLᴴ from there: the switches set "
        "from the back-ends' factorisations and solves below; CHOLMOD's BLAS: "
     << cell(scale.value("blas", "?"))
     << ", on one thread (the engine runs frames in parallel itself). Reusing an earlier frame's factor to "
        "precondition conjugate gradients on E^R's frames was implemented and measured against refactorising "
        "(commit 33008f4): 4–6× slower on a gentle and two hard workloads at 250k triangles, so every E^R frame is "
        "factorised. Machine: "
     << cell(scale.value("machine", "?")) << "; " << cell(scale.value("compiler", "?")) << ". Targets at "
     << fixed(target("triangles"), 0) << " triangles: set-up ≤ " << fixed(target("setup_ms"), 0) << " ms, E^F ≤ "
     << fixed(target("frame_F_ms"), 0) << " ms a frame, E^R ≤ " << fixed(target("batch_R_ms"), 0)
     << " ms a batched frame growing at most " << fixed(target("growth_R"), 0) << "× from the size before, peak ≤ "
     << fixed(target("peak_MB"), 0)
     << " MB. A target is met when every run meets it, missed when none does, "
        "undecided otherwise (with five runs their least and largest bracket the median of runs with probability "
        "94%, whatever the runs' distribution; a growth's runs are every pairing of the two sizes'): "
     << (scale.value("verdict", json()).is_string() ? "targets met: " + met_cell(scale["verdict"])
                                                    : std::string("not measured at that size"))
     << " (E^R's batched frame grew " << fixed(scale.value("growth_R", json()), 1) << "× into the largest size).\n\n";
  if (!scale.value("target_verdicts", json::array()).empty()) {
    md << "| target at " << fixed(target("triangles"), 0)
       << " triangles | limit | median | runs (least–largest) | met | where the time goes (when not met) |\n"
          "|---|---|---|---|---|---|\n";
    for (const auto& v : scale["target_verdicts"]) {
      const json range = v.value("range", json());
      md << "| " << cell(v.value("target", "")) << " | " << fixed(v.value("limit", json()), 1) << " | "
         << fixed(v.value("measured", json()), 1) << " | "
         << (range.is_array() ? fixed(range[0], 1) + "–" + fixed(range[1], 1) : std::string("—")) << " | "
         << met_cell(v.value("verdict", json())) << " | "
         << cell(v.value("cause", json()).is_string() ? v["cause"].get<std::string>() : std::string("—")) << " |\n";
    }
    md << "\n";
  }
  md << "| triangles | set-up E^F (ms) | set-up E^R (ms) | frame E^F (ms) | frame E^R (ms) | batched frame E^R (ms) "
        "| peak (MB) |\n|---|---|---|---|---|---|---|\n";
  const auto both = [](const json& row, const std::string& key, int digits) {
    return fixed(row.value(key + "_ms", json()), digits) + " (" + fixed(row.value(key + "_cpu_ms", json()), digits) +
           ")";
  };
  for (const auto& row : scale.value("rows", json::array()))
    md << "| " << fixed(row.value("triangles", json()), 0) << " | " << both(row, "setup_F", 0) << " | "
       << both(row, "setup_R", 0) << " | " << both(row, "frame_F", 1) << " | " << both(row, "frame_R", 1) << " | "
       << fixed(row.value("batch_R_ms", json()), 1) << " | " << fixed(row.value("peak_MB", json()), 0) << " |\n";
  const json& p = scale.value("exponents", json::object());
  md << "| exponent p (cost ∝ n^p, from " << fixed(scale.value("exponents_from_triangles", json()), 0) << ") | "
     << fixed(p.value("setup_F_ms", json()), 2) << " | " << fixed(p.value("setup_R_ms", json()), 2) << " | "
     << fixed(p.value("frame_F_ms", json()), 2) << " | " << fixed(p.value("frame_R_ms", json()), 2) << " | "
     << fixed(p.value("batch_R_ms", json()), 2) << " | " << fixed(p.value("peak_MB", json()), 2) << " |\n\n";
  if (!scale.value("back_ends", json::array()).empty()) {
    md << "Each back-end on the same matrices (`backend_*`: E^F's real L with two right-hand sides, E^R's complex "
          "H(½) with one), CPU ms of the calling thread (a `backend_factor` or `backend_solve` runs on it "
          "alone; set-up and frames use the second core too, not counted here: the loops over triangles on large "
          "meshes, the simplicial factor's two groups of subtrees):\n\n| back-end | triangles | "
          "factor E^F | factor E^R | "
          "solve E^F | solve E^R | set-up E^F | set-up E^R | frame E^F | frame E^R |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& back_end : scale["back_ends"]) {
      for (const auto& row : back_end["rows"]) {
        md << "| " << back_end.value("name", "") << " | " << fixed(row.value("triangles", json()), 0);
        for (const char* key :
             {"factor_F", "factor_R", "solve_F", "solve_R", "setup_F", "setup_R", "frame_F", "frame_R"})
          md << " | " << fixed(row.value(std::string(key) + "_cpu_ms", json()), 1);
        md << " |\n";
      }
      const json& q = back_end.value("exponents", json::object());
      md << "| " << back_end.value("name", "") << " | exponent p";
      for (const char* key : {"factor_F", "factor_R", "solve_F", "solve_R", "setup_F", "setup_R", "frame_F", "frame_R"})
        md << " | " << fixed(q.value(std::string(key) + "_ms", json()), 2);
      md << " |\n";
    }
    md << "\n";
  }
  for (const auto& f : scale.value("figures", json::array()))
    if (f.get<std::string>().ends_with(".png")) md << "![cost against mesh size](" << f.get<std::string>() << ")\n\n";
}

/// A frame through `affinterp interpolate` at 1M triangles against the engine's own (bench_cli_scale, one run).
void write_engine_cli(std::ostringstream& md, const json& cli) {
  md << "### Through the CLI\n\n";
  if (cli.is_null()) {
    md << "Not measured: `reports/bench/bench_cli_scale.json` is absent (run `experiments/reproduce.sh`).\n\n";
    return;
  }
  md << "`build/bin/bench_cli_scale`: `affinterp interpolate --format npy --no-figures --metrics none` on "
        "`affinterp shapes strip-spiral --quads 2000x250` ("
     << fixed(cli.value("triangles", json()), 0)
     << " triangles, a strip 18.8 × 2 rolled 1.5 turns), run as a process for 2 frames and for the table's extra "
        "frames more: a frame through the CLI, writing included, is the difference over the extra frames; the engine's "
        "frame is `vertices_at(times)` of 8 frames on the same pair, per frame, in the benchmark's own process "
        "(glibc's default allocator; the CLI keeps freed arrays in its heap, `experiments/apps/cli/main.cpp`). "
        "Medians of the repetitions, the ratio with its 95% bootstrap interval. Machine: "
     << cell(cli.value("machine", "?")) << ". Target: the CLI within " << fixed(cli.value("target_ratio", json()), 1)
     << "× the engine (met when the interval lies at or below it): " << met_cell(cli.value("verdict", json()))
     << ". The CLI's frames written into memory (`/dev/shm`) instead of the temporary folder's file system show "
        "what writing them costs there.\n\n"
        "| energy | extra frames | CLI frame (ms) | engine frame (ms) | CLI / engine | repetitions | met | CLI frame "
        "into memory (ms) | into memory / engine |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : cli.value("rows", json::array()))
    md << "| E^" << row.value("energy", "") << " | " << fixed(row.value("extra_frames", json()), 0) << " | "
       << fixed(row.value("cli_frame_ms", json()), 1) << " | " << fixed(row.value("engine_frame_ms", json()), 1)
       << " | " << with_ci(row.value("ratio", json()), row.value("ratio_ci95", json()), 2) << " | "
       << row.value("repetitions", 0) << " | " << met_cell(row.value("verdict", json())) << " | "
       << fixed(row.value("cli_memory_frame_ms", json()), 1) << " | "
       << with_ci(row.value("memory_ratio", json()), row.value("memory_ratio_ci95", json()), 2) << " |\n";
  md << "\n";
}

}  // namespace

std::string render_markdown(const json& doc) {
  const json& claims = doc["claims"];
  std::map<std::string, int> counts;
  for (const auto& c : claims) ++counts[c["verdict"].get<std::string>()];

  std::ostringstream md;
  md << "# affinterp report\n\n"
     << "Which claims of Kaji et al., *Mathematical Analysis on Affine Maps for 2D Shape Interpolation* "
        "(SCA 2012) and Matsushita, *A Study on 2D Shape Interpolation Using Affine Maps* (thesis, 2015) "
        "hold, decided by computations this suite runs itself.\n\n"
     << "Generated " << doc.value("generated_at", "") << " with seed " << doc.value("seed", 0ull) << ", size `"
     << doc.value("size", "") << "`. Verdicts:";
  for (const auto& [verdict, n] : counts) md << " " << verdict << " " << n << ";";
  md << "\n\n## Claims\n\n";
  write_summary_table(md, claims);

  md << "\n## Verdicts\n\n"
        "- **confirmed**: holds on everything tried (exact computation where the claim is algebraic, "
        "otherwise a sweep whose size, seed and tolerance are stated).\n"
        "- **refuted**: fails; the counterexample can be re-verified from claims.json alone.\n"
        "- **corrected**: fails as printed, holds after the stated correction.\n"
        "- **reproduced** / **not-reproduced**: a measured figure compared with the paper's, on every recorded run "
        "of the benchmarks (`bench/history/`, one entry per run, machine named): on each run its 95% bootstrap "
        "interval over the benchmark's repetitions and processes lies inside / outside the band of values the "
        "claim's wording allows (stated in the claim's rule; an interval across an edge of the band leaves that run "
        "inconclusive), and every run says so.\n"
        "- **machine-dependent**: a measured figure reproduced on one recorded run and not on another: a property "
        "of the machine, not of the claim; the claim's table lists every run and its plot shows each run's "
        "interval against the band. Runs that decide and agree while others are undecided leave the claim "
        "inconclusive.\n"
        "- **inconclusive**: not decided; the finding says why.\n"
        "- **pending**: no check implemented yet.\n\n"
        "## Strength\n\n"
        "- **proved for all reals**: one complete formulation of the claim (and of its correction, if any) "
        "reduces, by the lemmas written out in `proofs/LEMMAS.md`, to first-order sentences over the reals each "
        "answered by two independent deciders (of QEPCAD B, Z3 and cvc5) and polynomial identities each checked by "
        "two independent checkers (GiNaC, an exact degree grid), citing no external theorem; a transcript with an "
        "error or a warning answers nothing. The sentence files and each decider's transcript are in `proofs/` "
        "and rerun with the tool alone. A proof may have several formulations: the lemma chain, and one taken "
        "as nearly as written from the paper's definition (Def 2.2.1: for all 0 <= s <= t <= 1; Def 2.2.2: for "
        "every t in [0, 1] and every unit v) with as few lemmas as a decider answers, each lemma it uses a "
        "sentence of its own. What was tried and not answered (tool, CPU time, memory, outcome), and what no "
        "decider can be given (a transcendental homotopy), is listed under \"Tried for the record\".\n"
        "- **proved, one decider (name)**: as above, but some sentence was answered by the named decider only.\n"
        "- **proved, citing (theorem)**: as above, with an external published theorem as a step (full reference "
        "given), and no formulation without it answered by two deciders.\n"
        "- Sentences marked **structural** are empty for propositional reasons alone and count as no evidence; "
        "a proof of structural sentences only proves nothing.\n"
        "- **exact counterexample**: the printed claim fails at an exact (rational) point anyone can re-verify. "
        "With \"rest proved\", the claim's proof section decides for all reals, by the deciders named, the "
        "sentences that fail as printed and those that hold (the correction, or what holds instead); otherwise "
        "a correction is checked on a grid or sample only.\n"
        "- **grid only** / **sample only**: checked on the stated grid or random sample (size, seed and "
        "tolerance in the evidence), not proved.\n"
        "- **measured**: a measured figure, with its 95% bootstrap interval over repeated runs, on each recorded "
        "machine.\n";

  std::string group;
  for (const auto& c : claims) {
    if (c.value("group", "") != group) {
      group = c.value("group", "");
      md << "\n## " << group << "\n\n";
    }
    write_claim_section(md, c);
  }

  write_engine_speed(md, doc.value("engine_speed", json()));
  write_engine_scale(md, doc.value("engine_scale", json()));
  write_engine_cli(md, doc.value("engine_cli", json()));
  md << "## How to reproduce\n\n"
        "From a fresh clone on Debian, `bash experiments/reproduce.sh` installs what is missing, builds, "
        "runs the benchmarks and writes this report and `claims.json`. One claim alone: "
        "`build/bin/affinterp claims --only ID`; with another seed: `--seed N`.\n\n"
        "## Environment\n\n| | |\n|---|---|\n";
  for (const auto& [key, value] : doc["environment"].items())
    md << "| " << key << " | " << cell(value.is_string() ? value.get<std::string>() : value.dump()) << " |\n";
  md << "| seed | " << doc.value("seed", 0ull) << " |\n";
  return md.str();
}

}  // namespace affinterp::report
