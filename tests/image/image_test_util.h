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

namespace lensrt::test {

// A textured ground truth in [0.2, 1]: 4-pixel checks plus a slow ripple,
// slightly different per channel.
double texturedTruth(int x, int y, int channel);

// A synthetic render of texturedTruth with a variance AOV: each R,G,B value
// is the mean of `spp` samples with relative standard deviation
// `sampleNoise` (so the mean's deviation is sampleNoise*truth/sqrt(spp)),
// and variance.R/G/B is the sample variance / spp, as a renderer writes it.
// `gain` scales the whole render; `shiftX` samples the truth one column over.
Image noisyRender(int width, int height, unsigned seed, int spp, double sampleNoise, double gain = 1.0,
                  int shiftX = 0);

}  // namespace lensrt::test
