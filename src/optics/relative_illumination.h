// Relative illumination: film irradiance across the field, from exact rays.
//
// For a Lambertian scene of uniform radiance L filling the field, the
// irradiance at film point x is E(x) = L * Omega(x), the projected solid
// angle of the directions from x that pass the whole lens:
//   Omega(x) = integral over passing points p of the plane z = rearZ of
//              cos^4(theta) / d^2 dA,
// theta the angle of the ray x -> p to the axis and d the axial distance from
// the film to that plane (dA cos(theta) / (d / cos(theta))^2 is the solid
// angle, times cos(theta) for the projection onto the film). It includes
// the cos^4 falloff, mechanical vignetting by every aperture, and pupil
// distortion. Relative illumination is RI(x) = E(x) / E(0). On the axis of a
// lens at infinity, Omega(0) = pi / (4 N^2) for its working f-number N.
//
// With a lens that models coatings each passing ray counts with its Fresnel
// transmittance (Omega is then the transmitted projected solid angle).
//
// The passing set is found by a coarse grid over a generous square, then
// integrated by the midpoint rule on a fine grid over its bounding box:
// deterministic, no sampling noise.
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
