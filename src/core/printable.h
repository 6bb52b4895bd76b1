// Text from a file or the command line echoed in an error message: printable
// ASCII only and at most `maxChars`, so that the error stays one readable
// line whatever the input holds.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace lensrt {

inline std::string printable(std::string_view text, std::size_t maxChars = 40) {
  std::string out;
  for (const char c : text.substr(0, maxChars)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > maxChars) out += "...";
  return out;
}

}  // namespace lensrt
