// Lowercase ASCII, for names matched case-insensitively: file extensions
// (".EXR" is ".exr"), lens-file keywords. Bytes outside A-Z stay as they are.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace lensrt {

inline std::string asciiLower(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

// The extension with its dot, lowercase: what picks a file's format.
inline std::string lowerExtension(const std::filesystem::path& file) {
  return asciiLower(file.extension().string());
}

}  // namespace lensrt
