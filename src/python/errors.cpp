#include "python/errors.h"

#include <filesystem>

#include "api/option_table.h"
#include "core/error.h"

namespace lensrt::python {

void registerErrors(pybind11::module_&) {
  pybind11::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      // The file named by the error may be a library lens or an option's
      // value rather than a path: only an absent path is "not found".
      std::error_code ec;
      const bool missing = !e.file().empty() && e.line() == 0 && !std::filesystem::exists(e.file(), ec) &&
                           (e.message().find("no such") != std::string::npos ||
                            e.message().find("not found") != std::string::npos);
      PyErr_SetString(missing ? PyExc_FileNotFoundError : PyExc_ValueError, e.what());
    } catch (const UsageError& e) {
      // The command line's words turned into Python's: each --flag becomes its keyword.
      PyErr_SetString(PyExc_ValueError, inKeywords(e.what()).c_str());
    }
  });
}

}  // namespace lensrt::python
