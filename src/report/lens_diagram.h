// A lens-design-book drawing of a lens: its elements to scale in meridional
// section, the stop, the film, the cardinal points and pupils, and ray fans
// traced exactly from three field angles; optionally one ghost path (an
// axial bundle from infinity reflected at two surfaces, optics/ghosts.h).
#pragma once

#include <optional>

#include "api/lens_view.h"
#include "report/svg_writer.h"

namespace lensrt {

struct DiagramGhost {
  int first = 0, second = 0;  // 0-based surfaces: reflected at `first`, then at `second` < first
};

Svg drawLensDiagram(const LensView& view, const std::optional<DiagramGhost>& ghost = std::nullopt);

}  // namespace lensrt
