#pragma once
// A JSON object from experiments/inputs (a frame's metrics.json entry) as the Python dict json.loads makes of it:
// the same keys, numbers and nulls (None) as the file the CLI writes.
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace affinterp::python {

inline pybind11::object dict_of(const nlohmann::json& entry) {
  return pybind11::module_::import("json").attr("loads")(entry.dump());
}

}  // namespace affinterp::python
