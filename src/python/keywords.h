// Scene.render's keywords, from the option table (api/option_table.h): each
// Python value is turned into its flag's text and parsed by the row, so the
// checks are the command line's and the errors name the keyword.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "api/option_table.h"
#include "api/render_spec.h"

namespace lensrt::python {

namespace py = pybind11;

// The row of a Scene.render keyword; null when none.
const Option* renderKeyword(const std::string& name);
// Sets `row` from a Python value (None: nothing). Raises ValueError naming the keyword.
void setKeyword(RenderSpec& spec, const Option& row, py::handle value);

// The keyword's default as Python writes it ("16", "'pinhole'", "None").
std::string pythonDefault(const Option& row);
// Its type in the stub ("int | None", "str | os.PathLike[str] | None", ...).
std::string stubType(const Option& row);
// The keyword lines of Scene.render's stub (python/lensrt/__init__.pyi),
// between its "generated" markers (tools/gen-reference writes them).
std::string renderStub();
// Scene.render's docstring: the signature line and a line or more per keyword.
std::string renderDocstring();
// The keywords besides the table's rows (camera_to_world, progress).
inline const std::vector<std::string>& pythonOnlyKeywords() {
  static const std::vector<std::string> names{"camera_to_world", "progress"};
  return names;
}

}  // namespace lensrt::python
