#include "reports/generator/proof_section.hpp"

#include "reports/generator/claim_lines.hpp"
#include "reports/generator/markdown.hpp"

namespace affinterp::report {
namespace {

using nlohmann::json;

/// One sentence's runs: each checker with its input file, its answer linked to its transcript, its time.
std::string sentence_runs(const json& sentence, const std::string& up) {
  std::string runs;
  for (const auto& r : sentence["runs"]) {
    // A decider's transcript is <sentence>.<tool>.out beside its input (experiments/proofs/transcript.hpp).
    const std::string tool = r.value("tool", ""), file = r.value("file", "");
    const bool decider = tool == "qepcad" || tool == "z3" || tool == "cvc5";
    std::ostringstream one;
    one.precision(2);
    one << std::fixed << "[" << tool << "](" << up << file << "): [" << r.value("result", "") << "](" << up;
    if (decider)
      one << file.substr(0, file.rfind('/') + 1) << sentence.value("name", "") << "." << tool << ".out";
    else
      one << file;
    one << ") " << r.value("seconds", 0.0) << " s";
    runs += (runs.empty() ? "" : "; ") + one.str();
  }
  return runs;
}

/// A formulation's sentences with each checker's result; whether one is structural.
bool write_sentences(std::ostringstream& md, const json& proof, const std::string& up) {
  md << "| sentence | meaning | result | each checker: its answer (transcript), the time it took |\n"
        "|---|---|---|---|\n";
  bool any_structural = false;
  for (const auto& s : proof["sentences"]) {
    const bool structural = s.value("structural", false);
    any_structural = any_structural || structural;
    md << "| " << cell(s.value("name", "")) << " | " << cell(s.value("meaning", "")) << " | " << s.value("result", "")
       << (structural ? " (structural)" : "") << " | " << cell(sentence_runs(s, up)) << " |\n";
  }
  return any_structural;
}

std::string cpu_cell(const json& attempt) {
  std::ostringstream cpu;
  cpu.precision(1);
  cpu << std::fixed;
  if (!attempt.value("cpu_seconds", json()).is_number()) return "—";
  cpu << attempt["cpu_seconds"].get<double>() << " s";
  return cpu.str();
}

std::string memory_cell(const json& attempt) {
  if (!attempt.value("max_rss_kb", json()).is_number()) return "—";
  return std::to_string(attempt["max_rss_kb"].get<long>() / 1024) + " MiB";
}

/// What was tried for the record: the attempted formulations' runs, answered or not, and the formulations'
/// unanswered runs: formulation, tool, CPU time, peak memory, outcome.
void write_attempts(std::ostringstream& md, const json& attempts, const std::string& up) {
  md << "**Tried for the record** (attempted formulations, each run with its outcome, and the runs that answered "
        "nothing; the label rests on the formulations above):\n\n"
        "| formulation | sentence | tool | CPU time | peak memory | outcome |\n|---|---|---|---|---|---|\n";
  for (const auto& a : attempts) {
    const std::string file = a.value("file", ""), tool = a.value("tool", "");
    md << "| " << cell(a.value("formulation", "")) << " | " << cell(a.value("sentence", "")) << " | "
       << (tool.empty()   ? "—"
           : file.empty() ? tool
                          : "[" + tool + "](" + up + file + ")")
       << " | " << cpu_cell(a) << " | " << memory_cell(a) << " | " << cell(a.value("outcome", "")) << " |\n";
  }
  md << "\n";
}

}  // namespace

void write_proof(std::ostringstream& md, const json& proof, const std::string& up) {
  md << "## Proof for all reals\n\nScope: " << proof.value("scope", "") << ". Method: " << proof.value("method", "")
     << ". Decided by " << checkers(proof) << ".\n\n";
  bool any_structural = write_sentences(md, proof, up);
  int k = 1;
  for (const auto& f : proof.value("formulations", json::array())) {
    md << "\n**Formulation " << ++k << ".** Method: " << f.value("method", "") << ". Decided by " << checkers(f)
       << ".\n\n";
    any_structural = write_sentences(md, f, up) || any_structural;
  }
  if (any_structural)
    md << "\n*Structural*: empty for propositional reasons alone (every polynomial atom replaced by a boolean, "
          "the sentence stays unsatisfiable), so no evidence for the claim; its weight rests on the lemmas.\n";
  md << "\n";
  if (proof.contains("attempts")) write_attempts(md, proof["attempts"], up);
}

}  // namespace affinterp::report
