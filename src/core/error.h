// The exception types for bad input. Library code throws InputError with the
// file (and line when known) and UsageError for a bad setting, naming the
// option; the command catches them once and prints one line (exit 1 and 2):
//   lensrt: error: FILE:LINE: what is wrong
//   lensrt: error: --focus: what is wrong
#pragma once

#include <stdexcept>
#include <string>

namespace lensrt {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string message, int line = 0)
      : std::runtime_error(format(file, message, line)),
        file_(std::move(file)),
        message_(std::move(message)),
        line_(line) {}

  const std::string& file() const { return file_; }
  const std::string& message() const { return message_; }
  int line() const { return line_; }

 private:
  static std::string format(const std::string& file, const std::string& message, int line) {
    if (file.empty()) return message;
    std::string s = file;
    if (line > 0) {
      s += ':';
      s += std::to_string(line);
    }
    s += ": ";
    s += message;
    return s;
  }
  std::string file_;
  std::string message_;
  int line_;
};

// A bad setting rather than a bad file: an option value the renderer cannot
// use (the command line's exit status 2; Python's ValueError). `option` is
// the command line's name for it, e.g. "--focus".
class UsageError : public std::runtime_error {
 public:
  UsageError(std::string option, const std::string& message)
      : std::runtime_error(option + ": " + message), option_(std::move(option)), message_(message) {}
  const std::string& option() const { return option_; }
  const std::string& message() const { return message_; }

 private:
  std::string option_;
  std::string message_;
};

}  // namespace lensrt
