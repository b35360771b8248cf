#include "experiments/proofs/identity.hpp"

#include "experiments/proofs/exact_grid.hpp"
#include "experiments/proofs/ginac_polynomial.hpp"
#include "experiments/proofs/step_nodes.hpp"

#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace affinterp::proofs {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The entries of a side: a matrix's entries row by row, a matrix-valued step's entries as entry nodes (each line
/// of the script then performs the step), or the scalar itself.
std::vector<GiNaC::ex> entries(const GiNaC::ex& side) {
  std::vector<GiNaC::ex> list;
  if (GiNaC::is_a<GiNaC::matrix>(side)) {
    for (std::size_t i = 0; i < side.nops(); ++i) list.push_back(side.op(i));
    return list;
  }
  const auto [rows, cols] = shape(side);
  if (rows == 0) return {side};
  for (unsigned k = 0; k < rows * cols; ++k) list.push_back(entry(side, k));
  return list;
}

/// Symbols of `e` by name; throws when two distinct symbols share a name (the script could not tell them apart).
void collect_symbols(const GiNaC::ex& e, std::map<std::string, GiNaC::ex>& by_name) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    const auto [at, added] = by_name.emplace(name, e);
    if (!added && !at->second.is_equal(e)) throw std::invalid_argument("identity: two symbols are both named " + name);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), by_name);
}

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

/// The sides as the script states them, read back with GiNaC's parser: what both checkers decide.
struct Script {
  std::string text;
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> sides;  ///< per entry, parsed from the text
};

Script write_script(const std::string& id, const Identity& identity) {
  const std::vector<GiNaC::ex> left = entries(identity.lhs), right = entries(identity.rhs);
  if (left.size() != right.size()) throw std::invalid_argument("identity " + identity.name + ": sides differ in shape");
  std::map<std::string, GiNaC::ex> by_name;
  collect_symbols(identity.lhs, by_name);
  collect_symbols(identity.rhs, by_name);
  GiNaC::symtab table;
  for (const auto& [name, symbol] : by_name) table[name] = symbol;

  Script script;
  std::ostringstream text;
  text << "# " << id << " / " << identity.name << ": " << identity.meaning << "\n"
       << "# Rerun: ginsh " << identity.name << ".ginsh  (prints 1 per line when the identity holds)\n";
  for (std::size_t i = 0; i < left.size(); ++i) {
    const std::string l = text_of(left[i]), r = text_of(right[i]);
    text << "is(normal((" << l << ")-(" << r << "))==0);\n";
    script.sides.emplace_back(read_script_expression(l, table), read_script_expression(r, table));
  }
  script.text = text.str();
  return script;
}

/// The lists of entries as GiNaC matrices (one column), for the grid checker.
GiNaC::ex column(const std::vector<GiNaC::ex>& list) {
  GiNaC::matrix m(static_cast<unsigned>(list.size()), 1);
  for (unsigned i = 0; i < list.size(); ++i) m(i, 0) = list[i];
  return m;
}

}  // namespace

ProofSentence prove_identity(const Identity& identity, const SentenceFiles& files) {
  const std::string id = files.reference.substr(files.reference.find_last_of('/') + 1);
  const Script script = write_script(id, identity);
  if (!files.dir.empty()) {
    std::filesystem::create_directories(files.dir);
    write_file(files.dir / (identity.name + ".ginsh"), script.text);
  }

  // Checker 1: GiNaC performs the steps (diff, subs, evalm, determinant) on a copy, then the normal form of each
  // difference.
  auto start = Clock::now();
  bool ginac_zero = true;
  std::string answers;
  for (const auto& [l, r] : script.sides) {
    const bool zero = (perform_steps(l) - perform_steps(r)).normal().is_zero();
    ginac_zero = ginac_zero && zero;
    answers += zero ? "1\n" : "0\n";
  }
  const double ginac_seconds = seconds_since(start);

  // Checker 2: exact integer evaluation on the degree grid.
  start = Clock::now();
  std::vector<GiNaC::ex> left, right;
  for (const auto& [l, r] : script.sides) left.push_back(l), right.push_back(r);
  const GridVerdict grid = grid_check(column(left), column(right));
  const double grid_seconds = seconds_since(start);

  if (!files.dir.empty()) {
    write_file(files.dir / (identity.name + ".ginsh.out"), answers);
    write_file(files.dir / (identity.name + ".grid.out"), to_text(grid));
  }
  if (ginac_zero != grid.zero)
    throw std::runtime_error("identity " + id + "/" + identity.name + ": GiNaC and the exact grid disagree");

  const std::string result = grid.zero ? "zero" : "non-zero";
  const std::string script_file = files.reference + "/" + identity.name + ".ginsh";
  return {identity.name,
          identity.meaning,
          result,
          {{"ginac", script_file, result, ginac_seconds}, {"exact-grid", script_file, result, grid_seconds}}};
}

std::vector<ProofSentence> prove_identities(const std::vector<Identity>& identities, const SentenceFiles& files) {
  std::vector<ProofSentence> sentences;
  for (const Identity& identity : identities) sentences.push_back(prove_identity(identity, files));
  return sentences;
}

Proof identity_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences) {
  return make_proof(std::move(scope), std::move(method), std::move(sentences));
}

Proof combined_proof(std::string scope, std::string method, std::vector<ProofSentence> identities,
                     std::vector<ProofSentence> sentences) {
  identities.insert(identities.end(), sentences.begin(), sentences.end());
  return make_proof(std::move(scope), std::move(method), std::move(identities));
}

bool contradicted(const Proof& proof) {
  for (const ProofSentence& s : proof.sentences)
    if (s.result == "non-zero" || s.result == "non-empty") return true;
  return false;
}

bool proves(const Proof& proof) {
  if (!proof.decided() || !proof.has_content()) return false;
  for (const ProofSentence& s : proof.sentences) {
    const bool identity = !s.runs.empty() && s.runs.front().tool == "ginac";
    if (s.result != (identity ? "zero" : "empty")) return false;
  }
  return true;
}

}  // namespace affinterp::proofs
