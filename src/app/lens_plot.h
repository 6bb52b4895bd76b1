// SVG plots of a lens's field performance from exact ray tracing:
// relative illumination, distortion and spot diagrams.
#pragma once

#include "app/lens_plot_setup.h"
#include "app/svg_writer.h"

namespace lensrt {

Svg plotRelativeIllumination(const LensView& view);
Svg plotDistortion(const LensView& view);
Svg plotSpotDiagrams(const LensView& view);

}  // namespace lensrt
