// Focusing and stopping down a lens.
#pragma once

#include "core/warnings.h"
#include "optics/lens_system.h"

namespace lensrt {

// Film distance (rear vertex -> film, mm) that focuses an on-axis object
// `objectDistanceMm` in front of the ENTRANCE PUPIL (kInfinity allowed): the
// thick-lens estimate, refined by exactly traced near-axis rays. Throws
// InputError(lens name, ...) when the object is closer than the lens can focus
// (at or inside its front focal point, or inside the lens).
double focusFilmDistance(const LensSystem& lens, double objectDistanceMm);

// The closest object distance (from the entrance pupil, mm) with a real image:
// beyond the front focal point and outside the glass.
double nearestRealImageDistanceMm(const LensSystem& lens);

// The lens's closest focus (from the entrance pupil, mm), which the cameras
// keep to: the prescription's closestFocusMm when its file gives one, else
// magnification 1:1; never nearer than nearestRealImageDistanceMm.
double closestFocusDistanceMm(const LensSystem& lens);

// The prescription with its stop scaled so the paraxial f-number is `fNumber`.
// Asking for a wider aperture than the design's stop allows clamps to the
// widest and warns through `warnings`. Throws InputError for fNumber <= 0.
LensPrescription stopDown(const LensPrescription& lens, double fNumber, Warnings& warnings);

}  // namespace lensrt
