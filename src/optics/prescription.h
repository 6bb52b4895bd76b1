// A lens prescription: the ordered spherical or even-aspheric surfaces of a
// lens, from the object (scene) side to the film, in millimetres.
//
// Surface i sits at the axial vertex position z_i (z_0 = 0, z_{i+1} = z_i +
// thickness_i). radius > 0 means the centre of curvature lies on the film side
// of the vertex (convex toward the scene), 0 means flat. `medium` fills the gap
// from surface i to surface i + 1 (after the last surface: the space to the
// film, always air in practice). The last surface's thickness is the nominal
// film distance of the design (0 when the source does not give it).
// Exactly one surface is the aperture stop (flat, medium unchanged across it).
// A surface is aspheric when its conic constant or any of A4..A16 is non-zero
// (optics/asphere.h); radius is then the base (vertex) radius.
#pragma once

#include <string>
#include <vector>

#include "optics/asphere.h"
#include "optics/glass.h"

namespace lensrt {

struct Surface {
  double radius = 0.0;            // mm, signed; 0 = flat
  double thickness = 0.0;         // mm, vertex to next vertex (or to the film)
  double apertureDiameter = 0.0;  // mm, clear aperture
  Medium medium;                  // after this surface
  bool isStop = false;
  double conic = 0.0;               // conic constant k (0: sphere)
  AsphericCoefficients aspheric{};  // A4, A6, ..., A16 (all 0: no polynomial)
  int line = 0;                     // line in the source file, for messages (0 when unknown)

  bool isAspheric() const {
    if (conic != 0.0) return true;
    for (const double a : aspheric)
      if (a != 0.0) return true;
    return false;
  }
  AsphereProfile profile() const { return {radius != 0.0 ? 1.0 / radius : 0.0, conic, aspheric}; }
  // Axial sag at height r (signed: + toward the film); r within the aperture.
  double sag(double r) const;
  // Extremes of the sag over the clear aperture: the most negative value
  // (<= 0) and the largest magnitude. For a sphere both are at the rim.
  double minSag() const;
  double maxAbsSag() const;
};

struct LensPrescription {
  std::string name;                   // library name (file stem), e.g. "dgauss-50mm"
  std::string description;            // e.g. "Double Gauss F/2, 22 deg HFOV"
  std::string source;                 // patent or book it was taken from
  double nominalFocalLengthMm = 0.0;  // 0 when unknown
  // The design's closest focus, from the entrance pupil as every lensrt focus
  // distance is (mm); 0 when the file gives none (closestFocusDistanceMm then
  // takes magnification 1:1).
  double closestFocusMm = 0.0;
  std::string file;  // where it was read from (for messages)
  std::vector<Surface> surfaces;

  int stopIndex() const;  // -1 when there is none
  bool hasAspheres() const;
  // Distance from the first to the last vertex (excludes the film distance).
  double length() const;
  // The same design scaled uniformly (radii, thicknesses, apertures).
  LensPrescription scaled(double factor) const;
};

// Limits that separate a lens from garbage; readers refuse beyond them.
inline constexpr int kMaxSurfaces = 200;
inline constexpr double kMaxLengthMm = 10000.0;  // any radius, thickness or aperture

// Throws InputError(file, message, line) when the prescription cannot be a
// real lens: bad numbers, no or several stops, aperture wider than its sphere
// (or than an asphere's domain), an aspheric stop,
// surfaces that cut into each other within their clear apertures.
void validatePrescription(const LensPrescription& lens);

}  // namespace lensrt
