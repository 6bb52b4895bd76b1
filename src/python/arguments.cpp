#include "python/arguments.h"

#include <fmt/core.h>

#include <cmath>
#include <limits>

namespace lensrt::python {

void badArgument(const char* name, const std::string& expected, py::handle got) {
  std::string shown = py::str(py::repr(got));
  if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
  throw py::value_error(fmt::format("{}: expected {}, got {} {}", name, expected,
                                    std::string(py::str(got.get_type().attr("__name__"))), shown));
}

bool isNone(py::handle value) {
  return value.is_none();
}

double toDouble(py::handle value, const char* name) {
  // bool is an int in Python, but fstop=True is a mistake.
  if (py::isinstance<py::bool_>(value) ||
      !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
        py::hasattr(value, "__float__")) ||
      py::isinstance<py::str>(value))
    badArgument(name, "a number", value);
  const double v = value.cast<double>();
  if (!std::isfinite(v)) badArgument(name, "a finite number", value);
  return v;
}

std::optional<double> toOptionalDouble(py::handle value, const char* name) {
  if (value.is_none()) return std::nullopt;
  return toDouble(value, name);
}

long long toInteger(py::handle value, const char* name, long long lo, long long hi) {
  if (py::isinstance<py::bool_>(value) || !py::hasattr(value, "__index__"))
    badArgument(name, "an integer", value);
  const py::int_ index = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  long long v = 0;
  try {
    v = index.cast<long long>();
  } catch (const py::cast_error&) {
    badArgument(name, fmt::format("an integer from {} to {}", lo, hi), value);
  }
  if (v < lo || v > hi) badArgument(name, fmt::format("an integer from {} to {}", lo, hi), value);
  return v;
}

bool toBool(py::handle value, const char* name) {
  if (!py::isinstance<py::bool_>(value)) badArgument(name, "True or False", value);
  return value.cast<bool>();
}

std::string toText(py::handle value, const char* name) {
  if (!py::isinstance<py::str>(value)) badArgument(name, "a string", value);
  return value.cast<std::string>();
}

std::string toPathText(py::handle value, const char* name) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = value.attr("__fspath__")();
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  }
  badArgument(name, "a path (str or os.PathLike)", value);
}

std::string toDistanceText(py::handle value, const char* name) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) badArgument(name, "a distance in metres or 'inf'", value);
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
    const double v = value.cast<double>();
    if (std::isinf(v) && v > 0) return "inf";
    if (std::isfinite(v) && v > 0) return fmt::format("{:.17g}", v);
  }
  badArgument(name, "a distance in metres > 0, or 'inf'", value);
}

std::string toSensorText(py::handle value, const char* name) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value) && py::len(value) == 2) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    return fmt::format("{:.17g}x{:.17g}", toDouble(s[0], name), toDouble(s[1], name));
  }
  badArgument(name, "'WxH' in mm or a (width, height) pair", value);
}

std::vector<std::string> toTextList(py::handle value, const char* name) {
  std::vector<std::string> out;
  if (value.is_none()) return out;
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      if (comma > start) out.push_back(text.substr(start, comma - start));
      start = comma + 1;
    }
    return out;
  }
  if (!py::isinstance<py::sequence>(value)) badArgument(name, "a string or a sequence of strings", value);
  for (const py::handle item : value) out.push_back(toText(item, name));
  return out;
}

py::array_t<double, py::array::c_style> toFiniteMatrix(py::handle value, const char* name,
                                                       py::ssize_t columns, py::ssize_t rows) {
  const std::string shape = rows < 0 ? fmt::format("an N x {} array of numbers", columns)
                                     : fmt::format("a {} x {} array of numbers", rows, columns);
  py::array numbers;
  try {
    numbers = py::array::ensure(value);
  } catch (const py::error_already_set&) {
  }
  if (!numbers || numbers.dtype().kind() == 'O' || numbers.dtype().kind() == 'U' ||
      numbers.dtype().kind() == 'S' || numbers.dtype().kind() == 'c')
    badArgument(name, shape, value);
  auto matrix = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(numbers);
  if (!matrix || matrix.ndim() != 2 || matrix.shape(1) != columns || (rows >= 0 && matrix.shape(0) != rows))
    throw py::value_error(fmt::format("{}: expected {}, got shape {}", name, shape,
                                      std::string(py::str(numbers.attr("shape")))));
  const double* data = matrix.data();
  for (py::ssize_t i = 0; i < matrix.size(); ++i)
    if (!std::isfinite(data[i]))
      throw py::value_error(fmt::format("{}: row {} holds a NaN or infinite value", name, i / columns));
  return matrix;
}

// How far a pose's 3x3 part may be from a rotation (float32 poses pass).
constexpr double kRigidTolerance = 1e-4;

Transform toPose(py::handle value) {
  const auto m = toFiniteMatrix(value, "camera_to_world", 4, 4);
  const auto at = [&](int r, int c) { return m.at(r, c); };
  Transform::Matrix matrix{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix[r][c] = at(r, c);
  bool rigid = at(3, 0) == 0 && at(3, 1) == 0 && at(3, 2) == 0 && at(3, 3) == 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += at(k, i) * at(k, j);
      rigid = rigid && std::abs(dot - (i == j ? 1.0 : 0.0)) < kRigidTolerance;
    }
  const double det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                     at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                     at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  if (!rigid || det < 0)
    throw py::value_error(
        "camera_to_world: expected a rigid 4 x 4 pose (an orthonormal, right-handed 3 x 3 rotation, a "
        "translation in metres, last row 0 0 0 1); the camera looks down its -Z axis with +Y up (glTF's "
        "convention; for an OpenCV pose negate its Y and Z columns)");
  return Transform(matrix);
}

}  // namespace lensrt::python
