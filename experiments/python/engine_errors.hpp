#pragma once
// The engines' refusals as Python's ValueError: an error escapes a released GIL as a C++ exception, and
// std::invalid_argument becomes ValueError once the GIL is held again (pybind11's translation).
#include "theory/global/refused_problem.hpp"

#include <stdexcept>
#include <string>

namespace affinterp::python {

/// The engine's answer to `call`, a time out of range or a refused problem as std::invalid_argument.
template <class Call>
auto translated(Call call) {
  try {
    return call();
  } catch (const std::out_of_range& e) {
    throw std::invalid_argument(e.what());
  } catch (const global::RefusedProblem& e) {
    throw std::invalid_argument(std::string("refused: ") + e.what());
  }
}

}  // namespace affinterp::python
