// affinterp.decide: is a condition exactly where a homotopy is good for area (thesis Def 2.2.1) or norm
// (Def 2.2.2)? Decided for all reals by QEPCAD B and Z3, as `affinterp decide --json`
// (experiments/proofs/decide_condition.hpp).
#include "experiments/proofs/decide_condition.hpp"
#include "experiments/python/arrays.hpp"
#include "experiments/python/bindings.hpp"
#include "theory/logic/condition_parser.hpp"

#include <pybind11/stl.h>

namespace affinterp::python {

namespace {

py::dict decide(const std::string& condition_text, const std::string& homotopy, const std::string& notion,
                double timeout, int dim) {
  using namespace affinterp::proofs;
  if (!(timeout >= 1 && timeout <= 600)) value_error("timeout: expected seconds in [1, 600]");
  const AtlasCell* found = nullptr;
  try {
    found = &decide_cell(dim, homotopy, notion);
  } catch (const std::invalid_argument& e) {
    value_error(e.what());
  }
  const AtlasCell& cell = *found;
  logic::Formula condition;
  try {
    condition = logic::parse_condition(condition_text, cell.variables, cell.macros);
  } catch (const std::invalid_argument& e) {
    value_error(std::string("bad condition: ") + e.what());
  }
  ConditionVerdict v;
  {
    py::gil_scoped_release unlocked;
    v = decide_condition(cell, condition, {.seconds = timeout, .wall_factor = 1});
  }
  py::dict out;
  out["verdict"] = std::string(to_string(v.verdict));
  out["counterexample"] = py::none();
  if (v.counterexample) {
    py::dict c;
    for (const std::string& name : cell.variables) c[name.c_str()] = exact::to_string(v.counterexample->point.at(name));
    c["condition"] = v.counterexample->condition;
    c["property"] = v.counterexample->property;
    out["counterexample"] = c;
  }
  if (v.verdict == ConditionVerdict::Verdict::unknown) out["reason"] = v.reason;
  return out;
}

}  // namespace

void bind_decide(py::module_& m) {
  m.def("decide", &decide, py::arg("condition"), py::arg("homotopy"), py::arg("notion"), py::kw_only(),
        py::arg("timeout") = 25.0, py::arg("dim") = 2,
        R"(Whether `condition` holds exactly where `homotopy` ('linear', 'svd', 'polar', 'exp-log') is good for
`notion` ('area': thesis Def 2.2.1, 'norm': Def 2.2.2), decided for all reals by QEPCAD B and Z3 (both must
be installed), as `affinterp decide --json`. Variables: linear a, b, c, d (A = [[a, b], [c, d]]); polar and
exp-log x, y, h (S = [[x, h], [h, y]]); svd x, y (and beta for the norm); tr and det everywhere.
With dim=3 (3x3 maps, notions 'volume' and 'norm'): linear volume c1, c2, c3 (the invariants of A - I);
linear norm a11 ... a33; polar, svd (volume) and exp-log l1, l2, l3 (the singular values of A), as
`affinterp decide --dim 3 --help` lists them.
Returns {'verdict': 'equivalent' | 'not-equivalent' | 'unknown', 'counterexample': None or
{variable: 'p/q', 'condition': bool, 'property': bool}, and 'reason' when unknown}. ValueError on a bad
condition (the CLI's message).)");
}

}  // namespace affinterp::python
