#include "python/keywords.h"

#include <fmt/core.h>

#include "api/option_parsers.h"
#include "core/error.h"
#include "python/arguments.h"

namespace lensrt::python {
namespace {

bool isNumber(py::handle v) {
  return !py::isinstance<py::bool_>(v) && !py::isinstance<py::str>(v) &&
         (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v) || py::hasattr(v, "__float__"));
}

std::string numberArgument(py::handle v, const char* name) {
  return fmt::format("{:.17g}", toDouble(v, name));
}

std::string valueText(const Option& row, py::handle v) {
  const char* name = row.keyword.c_str();
  switch (row.python) {
    case PyValue::Text:
      return toText(v, name);
    case PyValue::Path:
      return toPathText(v, name);
    case PyValue::Number:
      return numberArgument(v, name);
    case PyValue::Integer:
      if (py::isinstance<py::bool_>(v) || !py::hasattr(v, "__index__")) badArgument(name, "an integer", v);
      return py::str(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr())));
    case PyValue::Switch:
      if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "on" : "off";
      return toText(v, name);
    case PyValue::NumberOrText:
      if (py::isinstance<py::str>(v)) return v.cast<std::string>();
      if (py::isinstance<py::float_>(v) && std::isinf(v.cast<double>()) && v.cast<double>() > 0)
        return row.numberPrefix + "inf";
      if (!isNumber(v)) badArgument(name, "a number or text", v);
      return row.numberPrefix + numberArgument(v, name);
    case PyValue::Pair:
      if (py::isinstance<py::str>(v)) return v.cast<std::string>();
      if (isNumber(v)) return numberArgument(v, name);
      if (py::isinstance<py::sequence>(v) && py::len(v) == 2) {
        const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
        return numberArgument(s[0], name) + row.separator + numberArgument(s[1], name);
      }
      badArgument(name, "a pair of numbers or text", v);
    case PyValue::List:
      if (py::isinstance<py::str>(v)) return v.cast<std::string>();
      if (py::isinstance<py::sequence>(v)) {
        std::string text;
        for (const py::handle item : v) {
          text += text.empty() ? "" : std::string(1, row.separator);
          text += isNumber(item) ? numberArgument(item, name) : toText(item, name);
        }
        return text;
      }
      badArgument(name, "a sequence or a comma-separated string", v);
  }
  badArgument(name, "a value", v);
}

}  // namespace

const Option* renderKeyword(const std::string& name) {
  for (const Option& row : optionTable())
    if (row.keyword == name && row.renderKeyword) return &row;
  return nullptr;
}

void setKeyword(RenderSpec& spec, const Option& row, py::handle value) {
  if (value.is_none()) return;
  const std::string text = valueText(row, value);
  try {
    row.set(spec, text);
  } catch (const UsageError& e) {
    throw py::value_error(inKeywords(e.what()));
  }
}

std::string pythonDefault(const Option& row) {
  static const RenderSpec defaults;
  const std::string shown = row.show(defaults);
  if (shown == "default" || shown.empty() || shown == "frame" || shown == "centre") return "None";
  const bool number = shown.find_first_not_of("0123456789.-e") == std::string::npos;
  switch (row.python) {
    case PyValue::Number:
    case PyValue::Integer:
      return shown;
    case PyValue::NumberOrText:
    case PyValue::Pair:
      return number ? shown : "\"" + shown + "\"";
    default:
      return "\"" + shown + "\"";
  }
}

std::string stubType(const Option& row) {
  std::string type;
  switch (row.python) {
    case PyValue::Text:
      type = "str";
      break;
    case PyValue::Path:
      type = "_Path";
      break;
    case PyValue::Number:
      type = "float";
      break;
    case PyValue::Integer:
      type = "int";
      break;
    case PyValue::Switch:
      type = "str | bool";
      break;
    case PyValue::NumberOrText:
      type = "float | str";
      break;
    case PyValue::Pair:
      type = "tuple[float, float] | float | str";
      break;
    case PyValue::List:
      type = "Sequence[str | int] | str";
      break;
  }
  return pythonDefault(row) == "None" ? type + " | None" : type;
}

std::string renderStub() {
  std::string stub;
  for (const Option& row : optionTable())
    if (row.renderKeyword && !row.keyword.empty())
      stub += "        " + row.keyword + ": " + stubType(row) + " = " + pythonDefault(row) + ",\n";
  stub += "        camera_to_world: npt.ArrayLike | None = None,\n";
  stub += "        progress: Callable[[int, int], bool | None] | None = None,\n";
  return stub;
}

std::string renderDocstring() {
  std::string signature = "render(";
  std::string keywords;
  std::size_t column = 7;
  for (const Option& row : optionTable()) {
    if (!row.renderKeyword || row.keyword.empty()) continue;
    const std::string item = row.keyword + "=" + pythonDefault(row) + ", ";
    if (column + item.size() > 100) {
      signature += "\n       ";
      column = 7;
    }
    signature += item;
    column += item.size();
    keywords += "  " + row.keyword + ": " + inKeywords(row.help) + "\n";
  }
  signature += "\n       camera_to_world=None, progress=None) -> RenderResult\n\n";
  return signature +
         "Renders the scene as `lensrt render` does, with the same bits for the same\n"
         "settings and seed. Keywords only, each the flag of the same name (None: its default):\n" +
         keywords +
         "  camera_to_world: a 4 x 4 rigid pose (metres) replacing the camera's; the\n"
         "    camera looks down its -Z axis with +Y up (glTF).\n"
         "  progress: callable(done_spp, total_spp) called between passes (which double\n"
         "    from 1 spp up to about a second each); returning False stops the render\n"
         "    there (RenderResult.finished is then False).\n"
         "A keyword given where it does nothing (fstop with the pinhole, say) gets a\n"
         "warning naming it. The GIL is released while rendering; Ctrl-C raises\n"
         "KeyboardInterrupt at the end of the pass in flight. Bad options raise\n"
         "ValueError naming the keyword; missing files FileNotFoundError.";
}

}  // namespace lensrt::python
