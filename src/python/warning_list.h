// lensrt's warnings as Python's: collected while the library works (often
// with the GIL released), then issued as UserWarnings, each prefixed with the
// file it is about when there is one, as the command line's warning lines are.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "core/warnings.h"

namespace lensrt::python {

class WarningList {
 public:
  explicit WarningList(std::string prefix = {}) : prefix_(std::move(prefix)) {}
  WarningList(const WarningList&) = delete;
  WarningList& operator=(const WarningList&) = delete;

  Warnings& sink() { return warnings_; }
  const std::vector<std::string>& messages() const { return list_; }
  // Issues them (with the GIL held); throws error_already_set when Python
  // turns warnings into errors.
  void emit() const { emit(prefix_, list_); }
  // Issues `messages` as emit() does, each prefixed with `prefix`.
  static void emit(const std::string& prefix, const std::vector<std::string>& messages) {
    for (const std::string& w : messages) {
      const std::string text = prefix.empty() ? w : prefix + ": " + w;
      if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 2) != 0) throw pybind11::error_already_set();
    }
  }

 private:
  std::string prefix_;
  std::vector<std::string> list_;
  Warnings warnings_{[this](const std::string& w) { list_.push_back(w); }};
};

}  // namespace lensrt::python
