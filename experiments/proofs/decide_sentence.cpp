#include "experiments/proofs/decide_sentence.hpp"

#include "experiments/proofs/subprocess.hpp"
#include "theory/logic/qepcad_input.hpp"
#include "theory/logic/smtlib_input.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <future>
#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {

namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

/// A temporary folder for sentences nobody keeps, removed with this object.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "affinterp-proof-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// The child-process limits of one decider run; `grace` seconds are added to the wall-clock limit.
ProcessLimits process_limits(const DeciderLimits& limits, double grace) {
  return {.wall_seconds = limits.seconds * limits.wall_factor + grace,
          .cpu_seconds = limits.seconds,
          .address_space_bytes = limits.address_space_bytes};
}

/// The output kept beside the input: timings removed, and a last line when the wall limit stopped the tool.
std::string kept_output(const ProcessResult& r, const DeciderLimits& limits) {
  std::string out = without_timings(r.output);
  if (r.timed_out) {
    std::ostringstream note;
    note << "# stopped at the limit of " << limits.seconds << " s of CPU time (or "
         << limits.seconds * limits.wall_factor << " s of wall-clock time)\n";
    out += note.str();
  }
  return out;
}

DeciderRun run_qepcad(const fs::path& input, const std::vector<std::string>& variables, const DeciderLimits& limits) {
  const ProcessResult r =
      run_process({"qepcad", "+N" + std::to_string(limits.qepcad_cells), "-noecho"}, input, process_limits(limits, 0));
  write_text(input.string() + ".out", kept_output(r, limits));
  DeciderRun run{"qepcad", "", {}, r.seconds};
  if (r.not_found)
    run.answer.reason = "qepcad: not installed (Debian package qepcad)";
  else if (r.timed_out)
    run.answer.reason = "qepcad: no answer within the time limit";
  else
    run.answer = parse_qepcad(r.output, variables);
  return run;
}

DeciderRun run_z3(const fs::path& input, const DeciderLimits& limits) {
  const int wall = std::max(1, static_cast<int>(std::floor(limits.seconds * limits.wall_factor)));
  // z3's own wall-clock limit ends it cleanly; the process limits, a little later, are the backstop.
  const ProcessResult r = run_process(
      {"z3", "-T:" + std::to_string(wall), "-memory:" + std::to_string(limits.z3_megabytes), input.string()}, {},
      process_limits(limits, 2));
  write_text(input.string() + ".out", kept_output(r, limits));
  DeciderRun run{"z3", "", {}, r.seconds};
  if (r.not_found)
    run.answer.reason = "z3: not installed (Debian package z3)";
  else if (r.timed_out)
    run.answer.reason = "z3: no answer within the time limit";
  else
    run.answer = parse_z3(r.output);
  return run;
}

/// The QEPCAD variable list of the input just written (its second line), to name the witness coordinates.
std::vector<std::string> qepcad_variables(const std::string& input) {
  std::istringstream in(input);
  std::string title, list;
  std::getline(in, title);
  std::getline(in, list);
  std::vector<std::string> names;
  std::string name;
  for (const char c : list) {
    if (c == '(' || c == ')' || c == ',') {
      if (!name.empty()) names.push_back(name);
      name.clear();
    } else {
      name += c;
    }
  }
  return names;
}

}  // namespace

std::string SentenceDecision::reasons() const {
  std::string text;
  for (const DeciderRun& r : runs)
    if (r.answer.result == SetResult::unknown) text += (text.empty() ? "" : "; ") + r.answer.reason;
  return text;
}

SentenceDecision decide_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits) {
  std::optional<ScratchFolder> scratch;
  if (files.dir.empty()) scratch.emplace();
  const fs::path dir = scratch ? scratch->path() : files.dir;
  fs::create_directories(dir);
  const std::string title =
      (files.reference.empty() ? "" : fs::path(files.reference).filename().string() + " ") + sentence.name;

  const std::string qepcad_text =
      logic::to_qepcad(sentence.formula, {.title = title, .free = {}, .order = sentence.qepcad_order, .commands = {}});
  const fs::path qepcad_file = dir / (sentence.name + ".qepcad"), smt_file = dir / (sentence.name + ".smt2");
  write_text(qepcad_file, qepcad_text);
  write_text(smt_file, logic::to_smtlib(sentence.formula, title));

  // Both at once, one per core.
  auto qepcad = std::async(std::launch::async, run_qepcad, qepcad_file, qepcad_variables(qepcad_text), limits);
  DeciderRun z3 = run_z3(smt_file, limits);
  SentenceDecision decision;
  decision.name = sentence.name;
  decision.runs = {qepcad.get(), std::move(z3)};
  const std::string prefix = files.reference.empty() ? "" : files.reference + "/";
  decision.runs[0].file = prefix + sentence.name + ".qepcad";
  decision.runs[1].file = prefix + sentence.name + ".smt2";

  for (const DeciderRun& r : decision.runs) {
    if (r.answer.result == SetResult::unknown) continue;
    if (decision.result != SetResult::unknown && decision.result != r.answer.result) decision.disagreement = true;
    decision.result = r.answer.result;
  }
  if (decision.disagreement) decision.result = SetResult::unknown;
  if (decision.result == SetResult::non_empty) {
    // Z3's exact model first (it names every variable it constrains), then QEPCAD's sample point.
    for (const int k : {1, 0})
      if (const auto& w = decision.runs[k].answer.witness;
          w && (!decision.witness || (!decision.witness->exact && w->exact)))
        decision.witness = w;
    if (decision.witness)
      for (const std::string& v : logic::prenex(sentence.formula).bound_variables())
        decision.witness->point.try_emplace(v, 0);
  }
  return decision;
}

ProofSentence to_proof_sentence(const Sentence& sentence, const SentenceDecision& decision) {
  if (decision.disagreement)
    throw std::runtime_error("the deciders disagree on the sentence " + sentence.name + " (" + decision.runs[0].file +
                             ": qepcad " + std::string(to_string(decision.runs[0].answer.result)) + ", z3 " +
                             std::string(to_string(decision.runs[1].answer.result)) + ")");
  ProofSentence s{sentence.name, sentence.meaning, std::string(to_string(decision.result)), {}};
  for (const DeciderRun& r : decision.runs)
    s.runs.push_back({r.tool, r.file, std::string(to_string(r.answer.result)), r.seconds});
  return s;
}

ProofSentence prove_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits) {
  return to_proof_sentence(sentence, decide_sentence(sentence, files, limits));
}

Proof make_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences) {
  Proof proof{std::move(scope), std::move(method), {}, std::move(sentences)};
  for (const char* tool : {"qepcad", "z3"}) {
    bool decided_all = !proof.sentences.empty();
    for (const ProofSentence& s : proof.sentences) {
      bool decided = false;
      for (const ProofSentence::Run& r : s.runs) decided = decided || (r.tool == tool && r.result != "unknown");
      decided_all = decided_all && decided;
    }
    if (decided_all) proof.checked_by.push_back(tool);
  }
  return proof;
}

}  // namespace affinterp::proofs
