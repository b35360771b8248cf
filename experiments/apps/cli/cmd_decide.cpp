// `affinterp decide`: is a condition exactly where a homotopy is good for area or norm? Decided for all
// reals by QEPCAD B and Z3 (experiments/proofs/decide_condition.hpp).
#include "experiments/apps/cli/command.hpp"
#include "experiments/proofs/decide_condition.hpp"
#include "theory/logic/condition_parser.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

namespace affinterp::cli {

namespace {

using namespace affinterp::proofs;

struct DecideOptions {
  std::string homotopy, notion, condition;
  int dim = 2;
  bool json = false;
  double timeout = 25;
};

constexpr const char* footer = R"(Variables with --dim 2 (tr and det of the matrix named are macros in every cell):
  linear    a, b, c, d      A = [[a, b], [c, d]], det A > 0; A(t) = (1-t)I + tA
  polar     x, y, h         S = [[x, h], [h, y]] positive definite, the symmetric factor of A = R S;
  exp-log   x, y, h           the rotation R plays no part in either notion
  svd       x, y (, beta)   D = diag(x, y), x, y > 0, A = R_alpha D R_beta; for the norm also beta, the right
                            rotation's angle in radians (any real; A(t) = R_(t alpha)((1-t)I + tD)R_(t beta))
Variables with --dim 3 (notions volume and norm; reports/proofs/LEMMAS.md, "The 3D atlas"):
  linear volume   c1, c2, c3    tr M, the sum of M's principal 2x2 minors, det M for M = A - I;
                                det A = 1 + c1 + c2 + c3 > 0; det((1-t)I + tA) = 1 + c1 t + c2 t^2 + c3 t^3
  linear norm     a11 ... a33   the entries of A (row, column), det A > 0; macros p11 ... p33, q11 ... q33
                                (P = sym(A) - I, Q = A^T A - sym(A)), det, detP, detQ
  polar, svd      l1, l2, l3    the eigenvalues of S in A = R S, i.e. the singular values of A, all > 0;
  (volume),                     macros c1, c2, c3: the invariants of S - I. The rotations play no part;
  polar, exp-log                the 3D svd norm cell is open (no decide)
  (volume, norm)
Grammar:
  numbers 3, 0.25, .5, 1/3; + - * /; ^ with integer exponents (x^2, x^-1); parentheses;
  comparisons < <= > >= = != (== too; chains 0 < x <= 1); and or not (also && || !); true false.
  A comparison whose sides divide by a polynomial D is false where D = 0 (N/D op 0 is D != 0 and N*D op 0).
Output: "equivalent", or "not equivalent" with a counterexample in small exact rationals (re-verified by exact
evaluation, and by the suite's own exact decider for linear, polar and svd-area cells; in 3D by
theory/local/goodness3.hpp for all but exp-log volume, where it answers) and which side fails,
or "unknown" with the reason. Each decider gets at most --timeout seconds per side.
Exit status: 0 with a verdict (unknown included), 2 on a bad expression or usage.)";

void print_text(const AtlasCell& cell, const ConditionVerdict& v) {
  using V = ConditionVerdict::Verdict;
  std::cout << (v.verdict == V::equivalent       ? "equivalent"
                : v.verdict == V::not_equivalent ? "not equivalent"
                                                 : "unknown")
            << "\n";
  if (v.counterexample) {
    const Counterexample& c = *v.counterexample;
    std::cout << "  counterexample:";
    for (const std::string& name : cell.variables)
      std::cout << " " << name << " = " << exact::to_string(c.point.at(name));
    std::cout << "\n  the condition is " << (c.condition ? "true" : "false") << " there, but the "
              << (cell.dimension == 3 ? "3D " : "") << cell.id() << " homotopy is "
              << (c.property ? "good" : "not good") << " ("
              << (c.condition ? "condition-true-property-false" : "condition-false-property-true") << ")\n";
    std::cout << "  re-verified by exact evaluation"
              << (c.checked_by_suite ? std::string(" and by the suite's exact decider (theory/local/") +
                                           (cell.dimension == 3 ? "goodness3.hpp)" : "goodness.hpp)")
                                     : std::string())
              << "\n";
  }
  if (!v.reason.empty()) std::cout << "  " << (v.verdict == V::unknown ? "reason: " : "note: ") << v.reason << "\n";
  for (const SentenceDecision& side : v.sides) {
    std::cout << "  " << side.name << ":";
    for (const DeciderRun& r : side.runs)
      std::cout << " " << r.tool << " " << to_string(r.answer.result) << " (" << std::fixed << std::setprecision(1)
                << r.seconds << " s)";
    std::cout << "\n";
  }
}

void print_json(const AtlasCell& cell, const ConditionVerdict& v, double seconds) {
  nlohmann::json out = {{"verdict", to_string(v.verdict)}, {"counterexample", nullptr}, {"seconds", seconds}};
  if (v.counterexample) {
    nlohmann::json c = nlohmann::json::object();
    for (const std::string& name : cell.variables) c[name] = exact::to_string(v.counterexample->point.at(name));
    c["condition"] = v.counterexample->condition;
    c["property"] = v.counterexample->property;
    out["counterexample"] = c;
  }
  if (v.verdict == ConditionVerdict::Verdict::unknown) out["reason"] = v.reason;
  std::cout << out.dump() << "\n";
}

void run(const DecideOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const AtlasCell* found = nullptr;
  try {
    found = &decide_cell(options.dim, options.homotopy, options.notion);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
  const AtlasCell& cell = *found;
  logic::Formula condition;
  try {
    condition = logic::parse_condition(options.condition, cell.variables, cell.macros);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(std::string("bad condition: ") + e.what(), usage_error);
  }
  const ConditionVerdict v = decide_condition(cell, condition, {.seconds = options.timeout, .wall_factor = 1});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.json)
    print_json(cell, v, std::round(seconds * 100) / 100);
  else
    print_text(cell, v);
}

}  // namespace

void add_decide_command(CLI::App& app) {
  auto options = std::make_shared<DecideOptions>();
  CLI::App* cmd = app.add_subcommand(
      "decide",
      "Decide for all reals whether a condition is exactly where a homotopy is good for area (Def 2.2.1) or norm "
      "(Def 2.2.2) of 2x2 maps, or for volume or norm of 3x3 maps (--dim 3), with QEPCAD B and Z3 (both must be "
      "installed; answers within about a minute).");
  cmd->add_option("--dim", options->dim, "2 (2x2 maps, the default) or 3 (3x3 maps)")
      ->check(CLI::IsMember({2, 3}))
      ->capture_default_str();
  cmd->add_option("--homotopy", options->homotopy, "linear, svd, polar or exp-log")
      ->required()
      ->check(CLI::IsMember({"linear", "svd", "polar", "exp-log"}));
  cmd->add_option("--notion", options->notion, "area or norm (2D); volume or norm (3D)")
      ->required()
      ->check(CLI::IsMember({"area", "norm", "volume"}));
  cmd->add_option("--condition", options->condition, "The condition, in the grammar below")->required();
  cmd->add_flag("--json", options->json,
                "Print one JSON object {\"verdict\", \"counterexample\": {variables as \"p/q\" (\"p\" when q = 1), "
                "\"condition\", "
                "\"property\"} or null, \"seconds\"} (and \"reason\" when unknown)");
  cmd->add_option("--timeout", options->timeout, "Seconds each decider may take per side")
      ->check(CLI::Range(1.0, 600.0))
      ->capture_default_str();
  cmd->footer(footer);
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
