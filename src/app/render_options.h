// Parsing of `lensrt render`'s option values that are more than a number:
// --res, --env and --aov. Bad syntax throws CLI::ValidationError (exit 2).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "render/film.h"

namespace lensrt {

struct Resolution {
  int width = 0;
  int height = 0;  // 0: derive from the camera's aspect ratio
};

// "WxH" (e.g. 640x360) or "W" (height from the camera's aspect ratio).
Resolution parseResolution(const std::string& text);

struct EnvironmentSpec {
  std::optional<Rgb> constant;  // constant:V or constant:R,G,B
  std::string file;             // a lat-long .exr or .hdr
};
EnvironmentSpec parseEnvironment(const std::string& text);

AovSelection parseAovs(const std::vector<std::string>& names);

// "" when `text` is a valid --res / --env value, else why not (for CLI11 checks).
std::string checkResolution(const std::string& text);
std::string checkEnvironment(const std::string& text);

}  // namespace lensrt
