#include "optics/paraxial.h"

#include <cmath>
#include <stdexcept>

#include "core/constants.h"

namespace lensrt {
namespace {

// Ray-transfer matrix on (y, n u): [y', n'u'] = [[a, b], [c, d]] [y, n u].
struct Matrix2 {
  double a = 1, b = 0, c = 0, d = 1;
  Matrix2 operator*(const Matrix2& m) const {
    return {a * m.a + b * m.c, a * m.b + b * m.d, c * m.a + d * m.c, c * m.b + d * m.d};
  }
};

Matrix2 refraction(double radius, double n1, double n2) {
  return {1, 0, radius == 0.0 ? 0.0 : -(n2 - n1) / radius, 1};
}
Matrix2 transfer(double thickness, double n) {
  return {1, thickness / n, 0, 1};
}

// Matrix from just before surface `first` to just after surface `last`
// (inclusive), with the transfers between them.
Matrix2 groupMatrix(const LensPrescription& lens, int first, int last) {
  Matrix2 m;
  for (int i = first; i <= last; ++i) {
    const double n1 = i > 0 ? lens.surfaces[i - 1].medium.nd : 1.0;
    const Surface& s = lens.surfaces[i];
    if (i > first) m = transfer(lens.surfaces[i - 1].thickness, n1) * m;
    m = refraction(s.radius, n1, s.medium.nd) * m;
  }
  return m;
}

// Distances where a conjugate lies at infinity stay finite so nothing downstream sees NaN.
double safeDivide(double num, double den) {
  if (std::abs(den) < 1e-300) return std::copysign(1e300, num) * (den < 0 ? -1 : 1);
  return num / den;
}

}  // namespace

ParaxialData computeParaxial(const LensPrescription& lens) {
  ParaxialData p;
  const int n = static_cast<int>(lens.surfaces.size());
  const Matrix2 system = groupMatrix(lens, 0, n - 1);
  if (std::abs(system.c) < 1e-12) throw std::domain_error("the lens is afocal (no focal length)");
  p.efl = -1.0 / system.c;
  p.bfl = -system.a / system.c;
  p.ffl = -system.d / system.c;
  p.lastVertexZ = lens.length();
  p.frontFocalZ = -p.ffl;
  p.rearFocalZ = p.lastVertexZ + p.bfl;
  p.frontPrincipalZ = p.frontFocalZ + p.efl;
  p.rearPrincipalZ = p.rearFocalZ - p.efl;

  p.stopIndex = lens.stopIndex();
  if (p.stopIndex < 0) return p;
  const int s = p.stopIndex;
  for (int i = 0; i < s; ++i) p.stopZ += lens.surfaces[i].thickness;
  p.stopDiameter = lens.surfaces[s].apertureDiameter;
  // Front group: first vertex -> stop plane (the stop itself does not refract).
  Matrix2 front;
  if (s > 0)
    front = transfer(lens.surfaces[s - 1].thickness, lens.surfaces[s - 1].medium.nd) *
            groupMatrix(lens, 0, s - 1);
  p.entrancePupilZ = safeDivide(front.b, front.a);
  p.entrancePupilDiameter = std::abs(safeDivide(p.stopDiameter, front.a));
  // Rear group: stop plane -> last vertex, then to the conjugate of the stop.
  const Matrix2 rear = groupMatrix(lens, s, n - 1);
  const double d = -safeDivide(rear.b, rear.d);
  p.exitPupilZ = p.lastVertexZ + d;
  p.exitPupilDiameter = std::abs(p.stopDiameter * (rear.a + d * rear.c));
  p.fNumber = safeDivide(std::abs(p.efl), p.entrancePupilDiameter);
  return p;
}

FieldOfView fieldOfView(double imageDistanceMm, double sensorWidthMm, double sensorHeightMm) {
  const auto angle = [&](double size) {
    return 2.0 * std::atan2(size / 2.0, std::abs(imageDistanceMm)) * 180.0 / kPi;
  };
  return {angle(std::hypot(sensorWidthMm, sensorHeightMm)), angle(sensorWidthMm), angle(sensorHeightMm)};
}

Conjugate paraxialConjugate(const ParaxialData& p, double objectDistanceMm) {
  Conjugate c;
  const double f = p.efl;
  if (std::isinf(objectDistanceMm)) {
    c.objectDistanceFromH = kInfinity;
    c.imageDistance = f;
    c.imageZ = p.rearFocalZ;
    c.filmDistance = p.bfl;
    c.magnification = 0.0;
    return c;
  }
  const double objectZ = p.entrancePupilZ - objectDistanceMm;
  const double sH = p.frontPrincipalZ - objectZ;
  if (f <= 0.0 || sH <= f * (1.0 + 1e-9))
    throw std::domain_error("the object is at or inside the front focal point");
  c.objectDistanceFromH = sH;
  c.imageDistance = f * sH / (sH - f);
  c.imageZ = p.rearPrincipalZ + c.imageDistance;
  c.filmDistance = c.imageZ - p.lastVertexZ;
  c.magnification = -c.imageDistance / sH;
  return c;
}

DepthOfField depthOfField(double f, double N, double c, double s) {
  const double f2 = f * f;
  const double spread = N * c * (s - f);
  DepthOfField dof;
  dof.nearLimit = s * f2 / (f2 + spread);
  const double farDen = f2 - spread;
  dof.farLimit = farDen > 0.0 ? s * f2 / farDen : kInfinity;
  return dof;
}

double hyperfocalDistance(double f, double N, double c) {
  return f * f / (N * c) + f;
}

}  // namespace lensrt
