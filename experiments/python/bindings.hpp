#pragma once
// The parts of the affinterp Python module, one file each, gathered by module.cpp.
#include <pybind11/pybind11.h>

namespace affinterp::python {

void bind_interpolation(pybind11::module_& m);
void bind_local(pybind11::module_& m);
void bind_sym3(pybind11::module_& m);
void bind_decide(pybind11::module_& m);
void bind_pair(pybind11::module_& m);
void bind_mesh(pybind11::module_& m);
void bind_blend(pybind11::module_& m);
void bind_keyframes(pybind11::module_& m);

}  // namespace affinterp::python
