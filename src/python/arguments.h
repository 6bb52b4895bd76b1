// Python arguments to lensrt's options: every conversion names the argument
// and raises ValueError (never TypeError or a crash) for a wrong type, a
// wrong shape, NaN or a value out of range, as the issue of bad input asks.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "core/transform.h"

namespace lensrt::python {

namespace py = pybind11;

// "camera_to_world: expected ..., got str 'x'".
[[noreturn]] void badArgument(const char* name, const std::string& expected, py::handle got);

bool isNone(py::handle value);
double toDouble(py::handle value, const char* name);  // int or float, finite
std::optional<double> toOptionalDouble(py::handle value, const char* name);
long long toInteger(py::handle value, const char* name, long long lo, long long hi);
bool toBool(py::handle value, const char* name);
std::string toText(py::handle value, const char* name);      // str
std::string toPathText(py::handle value, const char* name);  // str or os.PathLike
// A distance in metres as the command line's text: a number, or text passed
// on as the flag's ("inf", "auto"), which the flag's own parser checks.
std::string toDistanceText(py::handle value, const char* name);
// "WxH" text or a (width, height) pair in mm, as text.
std::string toSensorText(py::handle value, const char* name);
// A sequence of strings, or one comma-separated string.
std::vector<std::string> toTextList(py::handle value, const char* name);

// An N x `columns` float64 C-contiguous array of finite values (a copy only
// when the input is not one already); `rows` -1 for any N.
py::array_t<double, py::array::c_style> toFiniteMatrix(py::handle value, const char* name,
                                                       py::ssize_t columns, py::ssize_t rows = -1);

// camera_to_world: a rigid 4 x 4 pose (its 3 x 3 part a rotation within
// 1e-4, float32 poses pass; last row 0 0 0 1), glTF's camera convention.
Transform toPose(py::handle value);

}  // namespace lensrt::python
