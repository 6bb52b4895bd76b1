// The parts of the module, one per concept (lens, scene and render, diff).
#pragma once

#include <pybind11/pybind11.h>

namespace lensrt::python {

void bindLens(pybind11::module_& module);
void bindScene(pybind11::module_& module);
void bindDiff(pybind11::module_& module);

}  // namespace lensrt::python
