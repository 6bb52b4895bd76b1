#include "oiio_plugin/plugin_call.h"

#include <cstdlib>

namespace lensrt::oiio {
namespace {

std::string& lastError() {
  thread_local std::string text;
  return text;
}

}  // namespace

void setLastError(const std::string& reason) {
  lastError() = reason;
}

std::string oneLine(const std::string& text, const std::string& fallback) {
  std::string line;
  for (const char c : text) {
    if (c == '\n' || c == '\r') {
      if (!line.empty() && line.back() != ' ') line += "; ";
    } else {
      line += c;
    }
  }
  while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
  return line.empty() ? fallback : line;
}

}  // namespace lensrt::oiio

extern "C" {

const char* lensrt_oiio_last_error(void) {
  return lensrt::oiio::lastError().c_str();
}

void lensrt_oiio_free(void* buffer) {
  std::free(buffer);
}

}  // extern "C"
