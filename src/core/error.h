// The one exception type for bad input. Library code throws it with the file
// (and line when known); the command catches it once and prints one line:
//   lensrt: error: FILE:LINE: what is wrong
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

}  // namespace lensrt
