#include "optics/ghosts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/paraxial.h"

namespace lensrt {
namespace {

// Index in front of surface k (the scene side) and behind it, at the d line.
double indexBefore(const LensPrescription& lens, int k) {
  return k > 0 ? lens.surfaces[std::size_t(k - 1)].medium.nd : 1.0;
}
double indexAfter(const LensPrescription& lens, int k) {
  return lens.surfaces[std::size_t(k)].medium.nd;
}
double curvature(const Surface& s) {
  return s.radius != 0.0 ? 1.0 / s.radius : 0.0;
}

// Vertex positions z_k from the first vertex.
std::vector<double> vertices(const LensPrescription& lens) {
  std::vector<double> z(lens.surfaces.size(), 0.0);
  for (std::size_t k = 1; k < z.size(); ++k) z[k] = z[k - 1] + lens.surfaces[k - 1].thickness;
  return z;
}

// A paraxial ray entering parallel to the axis at height 1 along a ghost
// path: its height at each surface it crosses (relative to that surface's
// clear radius), and its height and slope after the last surface.
struct GhostRay {
  double worstRatio = 0.0;  // max over crossings of |y| / clear radius
  double y = 0.0, u = 0.0, z = 0.0;
};

GhostRay traceGhost(const LensPrescription& lens, const std::vector<double>& z, int first, int second) {
  GhostRay r;
  double y = 1.0, u = 0.0, at = 0.0;
  const auto reach = [&](int k) {
    y += u * (z[std::size_t(k)] - at);
    at = z[std::size_t(k)];
    const double radius = lens.surfaces[std::size_t(k)].apertureDiameter / 2;
    r.worstRatio = std::max(r.worstRatio, std::abs(y) / radius);
  };
  const auto refract = [&](int k, double n1, double n2) {
    u = (n1 * u - y * curvature(lens.surfaces[std::size_t(k)]) * (n2 - n1)) / n2;
  };
  const auto reflect = [&](int k) { u = -u - 2 * curvature(lens.surfaces[std::size_t(k)]) * y; };
  const int last = int(lens.surfaces.size()) - 1;
  for (int k = 0; k < first; ++k) reach(k), refract(k, indexBefore(lens, k), indexAfter(lens, k));
  reach(first), reflect(first);
  for (int k = first - 1; k > second; --k) reach(k), refract(k, indexAfter(lens, k), indexBefore(lens, k));
  reach(second), reflect(second);
  for (int k = second + 1; k <= last; ++k) reach(k), refract(k, indexBefore(lens, k), indexAfter(lens, k));
  r.y = y, r.u = u, r.z = at;
  return r;
}

double reflectance(const LensPrescription& lens, Coating coating, int k) {
  return 1.0 - surfaceTransmittance(coating, indexBefore(lens, k), indexAfter(lens, k), 1.0, 1.0, 550.0);
}

}  // namespace

std::vector<GhostPath> ghostPaths(const LensPrescription& lens, Coating coating) {
  const ParaxialData paraxial = computeParaxial(lens);
  const std::vector<double> z = vertices(lens);
  const double filmZ = paraxial.rearFocalZ;
  const double frontRadius = lens.surfaces.front().apertureDiameter / 2;
  const double pupilRadius = paraxial.entrancePupilDiameter / 2;
  std::vector<int> reflecting;
  for (int k = 0; k < int(lens.surfaces.size()); ++k)
    if (indexBefore(lens, k) != indexAfter(lens, k)) reflecting.push_back(k);
  std::vector<GhostPath> ghosts;
  for (std::size_t a = 0; a < reflecting.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      GhostPath g;
      g.first = reflecting[a];
      g.second = reflecting[b];
      g.strength = reflectance(lens, coating, g.first) * reflectance(lens, coating, g.second);
      const GhostRay ray = traceGhost(lens, z, g.first, g.second);
      // Heights scale with the entrance height h: every crossing stays within
      // its aperture up to h = 1 / worstRatio, and within the front element's.
      const double h = std::min(frontRadius, ray.worstRatio > 0 ? 1.0 / ray.worstRatio : frontRadius);
      g.passing = pupilRadius > 0 ? (h * h) / (pupilRadius * pupilRadius) : 0.0;
      const double yFilm = ray.y + ray.u * (filmZ - ray.z);
      g.sizeOnFilmMm = 2 * h * std::abs(yFilm);
      if (std::abs(ray.u) > 1e-12) g.focusFromFilmMm = ray.z - ray.y / ray.u - filmZ;
      ghosts.push_back(g);
    }
  return ghosts;
}

std::vector<GhostPath> strongestGhosts(const LensPrescription& lens, Coating coating) {
  std::vector<GhostPath> ghosts = ghostPaths(lens, coating);
  std::stable_sort(ghosts.begin(), ghosts.end(), [](const GhostPath& a, const GhostPath& b) {
    if (a.strength != b.strength) return a.strength > b.strength;
    return a.strength * a.passing > b.strength * b.passing;
  });
  return ghosts;
}

}  // namespace lensrt
