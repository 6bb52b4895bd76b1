#include "app/frame_sequence.h"

#include <fmt/core.h>

#include <cstdio>

#include "core/error.h"

namespace lensrt {

FrameRange parseFrames(const std::string& text) {
  FrameRange r;
  char end = 0;
  const int n = std::sscanf(text.c_str(), "%d:%d:%d%c", &r.first, &r.last, &r.step, &end);
  if (n != 2 && n != 3)
    throw UsageError("--frames", fmt::format("expected A:B or A:B:STEP (frame numbers), got '{}'", text));
  if (n == 2) r.step = 1;
  if (r.last < r.first || r.step < 1)
    throw UsageError("--frames", fmt::format("expected A <= B and STEP >= 1, got '{}'", text));
  if ((static_cast<long long>(r.last) - r.first) / r.step >= 1000000)
    throw UsageError("--frames", fmt::format("{} is over a million frames", text));
  return r;
}

std::string frameFileName(const std::string& pattern, int frame) {
  const std::size_t hash = pattern.find('#');
  if (hash != std::string::npos) {
    std::size_t end = hash;
    while (end < pattern.size() && pattern[end] == '#') ++end;
    return pattern.substr(0, hash) + fmt::format("{:0{}d}", frame, end - hash) + pattern.substr(end);
  }
  const std::size_t percent = pattern.find('%');
  if (percent != std::string::npos) {
    std::size_t end = percent + 1;
    int width = 0;
    if (end < pattern.size() && pattern[end] == '0') ++end;
    while (end < pattern.size() && pattern[end] >= '0' && pattern[end] <= '9')
      width = width * 10 + (pattern[end++] - '0');
    if (end < pattern.size() && pattern[end] == 'd' && width <= 16)
      return pattern.substr(0, percent) + fmt::format("{:0{}d}", frame, width) + pattern.substr(end + 1);
  }
  throw UsageError("-o", fmt::format("--frames needs a frame number in the output's name, as # marks or %04d "
                                     "(e.g. -o out/f.####.exr), got '{}'",
                                     pattern));
}

}  // namespace lensrt
