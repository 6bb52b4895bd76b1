// Helpers shared by the image-layer tests: a scratch directory per test and
// small synthetic images.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt::test {

// A fresh directory under the system temp dir, removed with its contents
// when the test ends (a failed test leaves nothing behind either).
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of the entries in the directory, sorted (to spot stray temporaries).
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

// Every channel of every pixel set to `value`.
Image constantImage(int width, int height, const std::vector<std::string>& channels, float value);

std::string readFileBytes(const std::filesystem::path& file);

// Runs a shell command, returning its exit status (or -1) and stdout.
struct CommandResult {
  int status = -1;
  std::string output;
};
CommandResult runCommand(const std::string& command);

// Quotes a path for /bin/sh.
std::string shellQuote(const std::string& s);

}  // namespace lensrt::test
