// When the film records: the shutter time, how the shutter opens and a
// rolling readout. render/shutter_timing.h is what the renderer makes of it.
#pragma once

#include <optional>

#include "render/shutter_timing.h"

namespace lensrt {

struct ShutterSpec {
  std::optional<double> seconds;  // none: 1/100 s (camera/exposure.h); 0: an instant
  double rampFraction = 0.0;      // 0: a box; else a trapezoid opening over this share
  double readoutSeconds = 0.0;    // a rolling shutter's readout; 0: a global shutter
  ShutterTiming::Readout readout = ShutterTiming::Readout::TopDown;

  double shutterSeconds() const;  // `seconds`, else the default
  // The samples' timing (without the camera's own motion).
  ShutterTiming timing() const;
  // How long a frame records the scene: the span a moving scene is posed over.
  double spanSeconds() const { return timing().spanSeconds(); }
};

}  // namespace lensrt
