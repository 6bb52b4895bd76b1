// Parsing of the render options that are more than a number: --res, --env
// and --aov (the option table's rows call these). Bad syntax throws
// UsageError (exit 2).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"
#include "scene/scene_file_access.h"

namespace lensrt {

struct Resolution {
  int width = 0;
  int height = 0;  // 0: derive from the camera's aspect ratio
};

// "WxH" (e.g. 640x360) or "W" (height from the camera's aspect ratio).
Resolution parseResolution(const std::string& text);

// --env (neither constant nor file: the default, see RenderJob), --env-rotate
// and --env-intensity.
struct EnvironmentSpec {
  bool none = false;            // --env none: the scene's own light alone, never the default sky
  std::optional<Rgb> constant;  // constant:V or constant:R,G,B
  std::string file;             // a lat-long .exr or .hdr
  double rotationDegrees = 0;   // about +Y, right-hand rule: +90 puts the map's centre at -X
  double intensity = 1;         // multiplies the radiance
};
EnvironmentSpec parseEnvironment(const std::string& text);

// What the scene's content may make lensrt read and hold (`lensrt render` and
// `lensrt compare`): --allow-external-files (or LENSRT_ALLOW_EXTERNAL_FILES=1)
// and --max-texture-memory MIB.
struct SceneAccessArgs {
  bool allowExternalFiles = false;
  std::uint64_t maxTextureMiB = defaultMaxTextureBytes() >> 20;
};
SceneReadLimits sceneReadLimits(const SceneAccessArgs& args);

AovSelection parseAovs(const std::vector<std::string>& names);

// Adaptive sampling from --noise-threshold (0: not given) and --min-spp
// (none: the default 16, or --spp when fewer) with --spp as the most: none without a threshold;
// UsageError for a threshold <= 0 or not finite, a --min-spp without a
// threshold, or one below 1 or above --spp.
std::optional<AdaptiveSampling> adaptiveSampling(double noiseThreshold, std::optional<int> minSpp, int spp);

}  // namespace lensrt
