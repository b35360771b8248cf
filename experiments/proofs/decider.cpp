#include "experiments/proofs/decider.hpp"

#include "experiments/proofs/subprocess.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace affinterp::proofs {

namespace {

/// The child-process limits of one decider run; `grace` seconds are added to the wall-clock limit.
ProcessLimits process_limits(const DeciderLimits& limits, double grace) {
  return {.wall_seconds = limits.seconds * limits.wall_factor + grace,
          .cpu_seconds = limits.seconds,
          .address_space_bytes = limits.address_space_bytes};
}

/// The command line and the standard input of one run.
std::pair<std::vector<std::string>, std::filesystem::path> command(const Decider& decider,
                                                                   const std::filesystem::path& input,
                                                                   const DeciderLimits& limits) {
  if (decider.tool == "qepcad") return {{"qepcad", "+N" + std::to_string(limits.qepcad_cells), "-noecho"}, input};
  if (decider.tool == "cvc5")  // --dump-models: a satisfiable sentence's model (a witness); --tlimit in ms
    return {
        {"cvc5", "--dump-models",
         "--tlimit=" + std::to_string(static_cast<long>(limits.seconds * limits.wall_factor * 1000)), input.string()},
        {}};
  // z3's own wall-clock limit ends it cleanly; the process limits, a little later, are the backstop.
  const int wall = std::max(1, static_cast<int>(std::floor(limits.seconds * limits.wall_factor)));
  // -model: the model of a satisfiable sentence (a witness) is printed without (get-model) in the input.
  return {
      {"z3", "-model", "-T:" + std::to_string(wall), "-memory:" + std::to_string(limits.z3_megabytes), input.string()},
      {}};
}

/// QEPCAD's variable list in the input (its second line), to name the witness coordinates.
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

const std::vector<Decider>& sentence_deciders() {
  static const std::vector<Decider> deciders = {
      {"qepcad", ".qepcad", "qepcad"}, {"z3", ".smt2", "z3"}, {"cvc5", ".smt2", "cvc5"}};
  return deciders;
}

std::string installed_version(const Decider& decider) {
  static std::mutex mutex;
  static std::map<std::string, std::string, std::less<>> versions;
  const std::lock_guard lock(mutex);
  if (const auto it = versions.find(decider.tool); it != versions.end()) return it->second;
  const ProcessResult r =
      run_process({"dpkg-query", "-W", "-f=${Version}", std::string(decider.debian_package)}, {}, {.wall_seconds = 30});
  const std::string version = r.exit_status == 0 && !r.timed_out ? r.output : "";
  versions.emplace(decider.tool, version);
  return version;
}

Transcript run_decider(const Decider& decider, const std::filesystem::path& input_file, const std::string& input_text,
                       const DeciderLimits& sentence_limits) {
  // cvc5, the third decider, gets at most 20 s of CPU: on the quantified sentences it does not decide it would
  // otherwise spend the whole limit (300 s on the literal levels) for no answer.
  DeciderLimits limits = sentence_limits;
  if (decider.tool == "cvc5") limits.seconds = std::min(limits.seconds, 20.0);
  const auto [argv, standard_input] = command(decider, input_file, limits);
  // The SMT solvers' own limits end them cleanly; the process limits, a little later, are the backstop.
  const ProcessResult r = run_process(argv, standard_input, process_limits(limits, decider.tool == "qepcad" ? 0 : 2));
  Transcript t{std::string(decider.tool),
               installed_version(decider),
               input_file.filename().string(),
               sha256_hex(input_text),
               limits.seconds,
               r.seconds,
               without_timings(r.output),
               r.cpu_seconds,
               r.max_rss_kb};
  if (r.not_found) {
    t.output += "# not installed (Debian package " + std::string(decider.debian_package) + ")\n";
  } else if (r.timed_out) {
    std::ostringstream note;
    note << "# stopped at the limit of " << limits.seconds << " s of CPU time (or "
         << limits.seconds * limits.wall_factor << " s of wall-clock time)\n";
    t.output += note.str();
  }
  return t;
}

DeciderAnswer answer_of(const Transcript& t, const std::string& input_text) {
  DeciderAnswer answer;
  if (t.output.find("# not installed") != std::string::npos) {
    answer.reason = t.tool + ": not installed";
  } else if (t.output.find("# stopped at the limit") != std::string::npos) {
    answer.reason = t.tool + ": no answer within the time limit";
  } else if (t.tool == "qepcad") {
    answer = parse_qepcad(t.output, qepcad_variables(input_text));
  } else {
    answer = parse_smt(t.output, t.tool);
  }
  return answer;
}

}  // namespace affinterp::proofs
