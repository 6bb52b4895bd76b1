// Relative illumination: film irradiance across the field, from exact rays.
//
// Design notes: docs/design/relative-illumination.md.
#pragma once

#include <vector>

#include "core/vec.h"
#include "optics/glass.h"
#include "optics/lens_system.h"

namespace lensrt {

struct FilmIrradiance {
  double projectedSolidAngle = 0.0;  // E / L, steradians
  double passingArea = 0.0;          // mm^2 on the plane z = rearZ
  Vec2d centroid;                    // of the passing area on that plane
};

// At film point (filmRadiusMm, 0) with the film at rearZ + filmDistanceMm.
FilmIrradiance filmIrradiance(const LensSystem& lens, double filmDistanceMm, double filmRadiusMm,
                              int grid = 96, double wavelengthNm = kWavelengthDNm);

struct RelativeIlluminationPoint {
  double filmRadiusMm = 0.0;
  double relative = 0.0;   // E(r) / E(0)
  double areaRatio = 0.0;  // passing area / passing area on the axis (vignetting alone)
  double cos4 = 0.0;       // cos^4 of the angle from the film point to the passing area's centroid
};

// `points` film radii evenly spaced over [0, maxFilmRadiusMm]. All zero when
// nothing passes on the axis.
std::vector<RelativeIlluminationPoint> relativeIlluminationCurve(const LensSystem& lens,
                                                                 double filmDistanceMm,
                                                                 double maxFilmRadiusMm, int points = 33,
                                                                 int grid = 96,
                                                                 double wavelengthNm = kWavelengthDNm);

}  // namespace lensrt
