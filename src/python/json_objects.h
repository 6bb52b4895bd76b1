// nlohmann::json documents (lens info --json, diff --json) as Python objects:
// the dicts Python users get are the command line's JSON, value for value.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace lensrt::python {

pybind11::object toPython(const nlohmann::json& value);

}  // namespace lensrt::python
