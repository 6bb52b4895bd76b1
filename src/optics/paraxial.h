// First-order (paraxial) optics of a prescription, by 2x2 ray-transfer
// matrices on (y, n*u). All positions are signed axial coordinates z in mm
// measured from the FIRST vertex, +z toward the film (see lens_system.h);
// object and image space are air, so nodal points equal principal points.
#pragma once

#include "optics/prescription.h"

namespace lensrt {

struct ParaxialData {
  double efl = 0.0;              // effective focal length (negative for a diverging lens)
  double bfl = 0.0;              // last vertex -> rear focal point F' (positive: F' behind it)
  double ffl = 0.0;              // front focal point F -> first vertex (positive: F in front)
  double frontFocalZ = 0.0;      // F
  double rearFocalZ = 0.0;       // F'
  double frontPrincipalZ = 0.0;  // H (= front nodal point N)
  double rearPrincipalZ = 0.0;   // H' (= rear nodal point N')
  double lastVertexZ = 0.0;      // prescription length
  int stopIndex = -1;
  double stopZ = 0.0;
  double stopDiameter = 0.0;
  double entrancePupilZ = 0.0;  // image of the stop through the front group
  double entrancePupilDiameter = 0.0;
  double exitPupilZ = 0.0;  // image of the stop through the rear group
  double exitPupilDiameter = 0.0;
  double fNumber = 0.0;  // efl / entrance pupil diameter
};

// Throws std::domain_error for an afocal system (no focal length).
ParaxialData computeParaxial(const LensPrescription& lens);

struct FieldOfView {
  double diagonalDeg = 0.0, horizontalDeg = 0.0, verticalDeg = 0.0;
};
// Full angles for a sensor (mm) behind a lens whose rear principal plane sits
// `imageDistanceMm` in front of the film (efl when focused at infinity).
FieldOfView fieldOfView(double imageDistanceMm, double sensorWidthMm, double sensorHeightMm);

// Gaussian conjugates for an object `objectDistanceMm` in front of the
// ENTRANCE PUPIL (infinity allowed).
struct Conjugate {
  double imageZ = 0.0;               // image position (z from the first vertex)
  double filmDistance = 0.0;         // last vertex -> image
  double imageDistance = 0.0;        // H' -> image
  double objectDistanceFromH = 0.0;  // object -> H (positive in front)
  double magnification = 0.0;        // lateral, negative (inverted real image)
};
// Throws std::domain_error when the object is at or inside the front focal
// point (no real image).
Conjugate paraxialConjugate(const ParaxialData& p, double objectDistanceMm);

// Depth of field of an ideal (thin) lens, the seed's formulas; distances from
// the lens (thick lens: from the front principal plane), any unit as long as
// all agree. far = +infinity past the hyperfocal distance.
struct DepthOfField {
  double nearLimit = 0.0, farLimit = 0.0;
};
DepthOfField depthOfField(double focalLength, double fNumber, double circleOfConfusion, double focusDistance);
// Focus distance beyond which the far limit is infinite: f^2 / (N c) + f.
double hyperfocalDistance(double focalLength, double fNumber, double circleOfConfusion);

}  // namespace lensrt
