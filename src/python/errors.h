// lensrt's exceptions as Python's: a missing file raises FileNotFoundError, a
// bad file or setting ValueError, each with the command line's message.
#pragma once

#include <pybind11/pybind11.h>

namespace lensrt::python {

void registerErrors(pybind11::module_& module);

}  // namespace lensrt::python
