// What a preview (.png, .jpg, .tif, .jp2, .webp) shows: its display-encoded
// R,G,B in [0,1], by default each linear value clamped to [0,1] under the
// sRGB curve (no exposure or tone curve), or OpenColorIO's display transform
// from the config's scene_linear role to a display and view (through the
// OpenImageIO plugin), then clamped.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

// An OpenColorIO display and view; empty names take the config's defaults.
struct DisplayTransform {
  std::string display;
  std::string view;
};

// width*height*3 values from `image`'s channels `rgb` (three indices).
// Throws InputError(file, ...) when the transform needs the plugin and it
// cannot be loaded, UsageError("--ocio-display", ...) when the config
// cannot make it.
std::vector<float> previewValues(const std::filesystem::path& file, const Image& image,
                                 const std::vector<int>& rgb, const std::optional<DisplayTransform>& display);

}  // namespace lensrt
