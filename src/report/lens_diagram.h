// A lens-design-book drawing of a lens: its elements to scale in meridional
// section, the stop, the film, the cardinal points and pupils, and ray fans
// traced exactly from three field angles.
#pragma once

#include "api/lens_view.h"
#include "report/svg_writer.h"

namespace lensrt {

Svg drawLensDiagram(const LensView& view);

}  // namespace lensrt
