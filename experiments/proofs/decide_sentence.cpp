#include "experiments/proofs/decide_sentence.hpp"

#include "experiments/proofs/structural.hpp"
#include "theory/logic/qepcad_input.hpp"
#include "theory/logic/smtlib_input.hpp"

#include <algorithm>
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

/// One decider's run on a written input: read from the stored transcript, or run now when there is no store.
DeciderRun decider_run(const Decider& decider, const Sentence& sentence, const fs::path& dir,
                       const std::string& input_text, const SentenceFiles& files, const DeciderLimits& limits) {
  const fs::path input = dir / (sentence.name + std::string(decider.input_extension));
  const std::string transcript_name = transcript_file_name(sentence.name, decider.tool);
  if (files.plan) files.plan->add({files.answers, sentence.name, decider, input_text, limits});
  std::optional<Transcript> transcript;
  if (files.answers.empty()) {
    transcript = run_decider(decider, input, input_text, limits);
  } else if (transcript = read_transcript(files.answers / transcript_name);
             !transcript || !transcript->answers(decider.tool, input_text)) {
    DeciderRun missing{std::string(decider.tool), "", {}, 0, {}, {}};
    missing.answer.reason = std::string(decider.tool) + ": no stored answer for this text of the sentence (" +
                            (transcript ? "the input changed" : "none") + "; `affinterp prove` decides it)";
    return missing;
  }
  if (files.answers.empty() || fs::weakly_canonical(dir) != fs::weakly_canonical(files.answers))
    write_transcript(dir / transcript_name, *transcript);
  return {
      std::string(decider.tool), "", answer_of(*transcript, input_text), transcript->seconds, transcript->cpu_seconds,
      transcript->max_rss_kb};
}

}  // namespace

std::vector<std::string> hong_projection(const logic::Formula& sentence) {
  // One operator per projection: from n variables down to 1, the first entry for 2-variate polynomials.
  const std::size_t variables = logic::prenex(sentence).bound_variables().size();
  std::string ops;
  for (std::size_t k = 1; k < variables; ++k) ops += (k > 1 ? ",h" : "h");
  return {"proj-operator (" + ops + ")"};
}

std::string SentenceDecision::answers() const {
  std::string text = name + " (";
  for (const DeciderRun& r : runs)
    text += (&r == &runs.front() ? "" : ", ") + r.tool + " " + std::string(to_string(r.answer.result));
  return text + ")";
}

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

  const std::string qepcad_text = logic::to_qepcad(
      sentence.formula,
      {.title = title, .free = {}, .order = sentence.qepcad_order, .commands = {}, .setup = sentence.qepcad_setup});
  const std::string smt_text = logic::to_smtlib(sentence.formula, title);
  const std::string prefix = files.reference.empty() ? "" : files.reference + "/";
  SentenceDecision decision;
  decision.name = sentence.name;
  decision.structural = is_structural(sentence.formula);
  // When the deciders run now, both at once, one per core.
  std::vector<std::future<DeciderRun>> runs;
  for (const Decider& decider : sentence_deciders()) {
    const std::string& text = decider.tool == "qepcad" ? qepcad_text : smt_text;
    write_text(dir / (sentence.name + std::string(decider.input_extension)), text);
    runs.push_back(std::async(std::launch::async, [&, text] {
      DeciderRun run = decider_run(decider, sentence, dir, text, files, limits);
      run.file = prefix + sentence.name + std::string(decider.input_extension);
      return run;
    }));
  }
  for (auto& run : runs) decision.runs.push_back(run.get());

  for (const DeciderRun& r : decision.runs) {
    if (r.answer.result == SetResult::unknown) continue;
    if (decision.result != SetResult::unknown && decision.result != r.answer.result) decision.disagreement = true;
    decision.result = r.answer.result;
  }
  if (decision.disagreement) decision.result = SetResult::unknown;
  if (decision.result == SetResult::non_empty) {
    // An exact model first (the SMT solvers name every variable they constrain), then QEPCAD's sample point.
    for (auto run = decision.runs.rbegin(); run != decision.runs.rend(); ++run)
      if (const auto& w = run->answer.witness; w && (!decision.witness || (!decision.witness->exact && w->exact)))
        decision.witness = w;
    if (decision.witness)
      for (const std::string& v : logic::prenex(sentence.formula).bound_variables())
        decision.witness->point.try_emplace(v, 0);
  }
  return decision;
}

ProofSentence to_proof_sentence(const Sentence& sentence, const SentenceDecision& decision) {
  if (decision.disagreement) throw std::runtime_error("the deciders disagree on the sentence " + decision.answers());
  ProofSentence s{sentence.name, sentence.meaning, std::string(to_string(decision.result)), {}, decision.structural};
  for (const DeciderRun& r : decision.runs)
    s.runs.push_back({r.tool, r.file, std::string(to_string(r.answer.result)), r.seconds, r.cpu_seconds, r.max_rss_kb,
                      r.answer.reason});
  return s;
}

ProofSentence prove_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits) {
  return to_proof_sentence(sentence, decide_sentence(sentence, files, limits));
}

Proof make_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences) {
  Proof proof{std::move(scope), std::move(method), {}, std::move(sentences)};
  // Each checker that ran, in the order it first appears, when it answered every sentence it ran on.
  std::vector<std::string> tools;
  for (const ProofSentence& s : proof.sentences)
    for (const ProofSentence::Run& r : s.runs)
      if (std::find(tools.begin(), tools.end(), r.tool) == tools.end()) tools.push_back(r.tool);
  for (const std::string& tool : tools) {
    bool answered_all = true;
    for (const ProofSentence& s : proof.sentences)
      for (const ProofSentence::Run& r : s.runs)
        answered_all = answered_all && (r.tool != tool || r.result != "unknown");
    if (answered_all) proof.checked_by.push_back(tool);
  }
  return proof;
}

}  // namespace affinterp::proofs
