// The "spp" channel of an adaptive render: the samples each pixel took.
// lensrt:spp then summarises it as "adaptive min=16 mean=41.37 max=1024"
// instead of holding one count.
#pragma once

#include <optional>
#include <string>

#include "image/image.h"

namespace lensrt {

inline constexpr const char* kSppChannel = "spp";

// "adaptive min=A mean=B max=C" over the image's spp channel; none without one.
std::optional<std::string> adaptiveSppSummary(const Image& image);

// Whether a lensrt:spp value is such a summary (not one count for every pixel).
bool isAdaptiveSpp(const std::string& value);

}  // namespace lensrt
