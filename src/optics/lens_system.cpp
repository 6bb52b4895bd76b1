#include "optics/lens_system.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/constants.h"
#include "optics/trace_lanes.h"

namespace lensrt {

namespace {

// refract() with the index ratio n1 / n2 already divided out.
inline bool refractEta(const Vec3d& d, const Vec3d& n, double eta, Vec3d& out) {
  const double cosI = -dot(n, d);
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T >= 1.0) return false;  // total internal reflection
  const double cosT = std::sqrt(1.0 - sin2T);
  // Unit in, unit out: no renormalisation needed (callers normalise once at the end).
  out = d * eta + n * (eta * cosI - cosT);
  return true;
}

// The sag at the edge of a surface's clear aperture (mm from its vertex):
// where its mount sits.
double rimSag(const Surface& s, double apertureRadius) {
  if (s.isAspheric())
    if (const std::optional<double> z = s.profile().sag(apertureRadius * apertureRadius)) return *z;
  if (s.radius == 0.0) return 0.0;
  const double R = s.radius, a = std::min(apertureRadius, std::abs(R));
  return R - std::copysign(std::sqrt(R * R - a * a), R);
}

}  // namespace

bool refract(const Vec3d& d, const Vec3d& n, double n1, double n2, Vec3d& out) {
  return refractEta(d, n, n1 / n2, out);
}

LensSystem::LensSystem(LensPrescription prescription, std::optional<Coating> coating)
    : prescription_(std::move(prescription)), coating_(coating) {
  validatePrescription(prescription_);
  paraxial_ = computeParaxial(prescription_);
  hasAspheres_ = prescription_.hasAspheres();
  double z = 0.0, ndBefore = 1.0;  // the scene is air
  for (const Surface& s : prescription_.surfaces) {
    TraceSurface t;
    t.z = z;
    t.radius = s.radius;
    t.invRadius = s.radius != 0.0 ? 1.0 / s.radius : 0.0;
    t.absInvRadius = std::abs(t.invRadius);
    t.invRadius2 = t.invRadius * t.invRadius;
    t.apertureRadius = s.apertureDiameter / 2.0;
    t.apertureRadius2 = t.apertureRadius * t.apertureRadius;
    t.isStop = s.isStop;
    if (s.isAspheric()) t.asphere = std::make_shared<const AsphereProfile>(s.profile());
    t.ndAfter = s.medium.nd;
    t.after = Dispersion::of(s.medium);
    t.etaFromFilm = t.ndAfter / ndBefore;
    t.etaFromScene = ndBefore / t.ndAfter;
    t.refracts = !t.isStop && t.ndAfter != ndBefore;
    t.rimZ = z + rimSag(s, t.apertureRadius);
    surfaces_.push_back(t);
    spheres_.push_back(
        {t.z, t.radius, t.absInvRadius, t.invRadius2, t.apertureRadius2, t.refracts ? t.etaFromFilm : 0.0});
    z += s.thickness;
    ndBefore = t.ndAfter;
  }
}

LensSystem LensSystem::withOpenRims() const {
  LensSystem open = *this;
  for (std::size_t i = 0; i < open.surfaces_.size(); ++i) {
    TraceSurface& s = open.surfaces_[i];
    if (s.asphere) continue;
    // The step keeps to the cap around the vertex by itself; a sphere's
    // hits lie within |R| of the axis.
    s.apertureRadius = s.radius == 0.0 ? kMaxLengthMm : std::abs(s.radius);
    s.apertureRadius2 = s.apertureRadius * s.apertureRadius;
    open.spheres_[i].apertureRadius2 = s.apertureRadius2;
  }
  return open;
}

// An even asphere: the exact hit by optics/asphere.h, the normal from the
// sag's derivative. Out of line: it is the rare case, and the spherical step
// below stays as it was (bit for bit).
template <bool kFromFilm>
bool LensSystem::asphereStep(const TraceSurface& s, double eta, Vec3d& o, Vec3d& d,
                             std::vector<Vec3d>* path) {
  const Vec3d p{o.x, o.y, o.z - s.z};
  const auto t = intersectAsphere(*s.asphere, s.apertureRadius, p, d);
  if (!t) return false;
  const Vec3d hit = p + d * *t;
  o = {hit.x, hit.y, hit.z + s.z};
  if (path) path->push_back(o);
  if (eta != 0.0) {
    const Vec3d n = asphereNormal(*s.asphere, hit);
    if (!refractEta(d, dot(n, d) > 0.0 ? -n : n, eta, d)) return false;
  }
  return kFromFilm ? d.z < 0.0 : d.z > 0.0;  // false: turned back
}

// One surface of the trace, everything inline. The trace is a chain of
// dependent square roots and divisions, so the step keeps them off each
// other's path: the refraction angle comes from the intersection's
// discriminant (cos i = sqrt(disc) / |R|), so its square root runs alongside
// the intersection's, and the roots -b -+ sqrt(disc) need no division (their
// absolute error, ~1e-16 |b| mm, is far below any optical tolerance).
// eta: the index ratio, or 0 when the surface does not bend the ray. False
// when the ray is blocked.
template <bool kFromFilm>
inline bool LensSystem::step(const TraceSurface& s, double eta, Vec3d& o, Vec3d& d,
                             std::vector<Vec3d>* path) {
  if (s.asphere) [[unlikely]]
    return asphereStep<kFromFilm>(s, eta, o, d, path);
  // Work relative to the vertex: a sphere through the vertex is
  // x^2 + y^2 + z^2 - 2 R z = 0, which avoids cancellation for large R.
  const Vec3d p{o.x, o.y, o.z - s.z};
  if (s.radius == 0.0) {
    if (d.z == 0.0) return false;
    const double t = -p.z / d.z;
    if (!(t >= -1e-9)) return false;
    const Vec3d hit = p + d * t;
    if (hit.x * hit.x + hit.y * hit.y > s.apertureRadius2) return false;
    o = {hit.x, hit.y, hit.z + s.z};
    if (path) path->push_back(o);
    if (eta == 0.0) return true;
    if (!refractEta(d, {0.0, 0.0, d.z > 0.0 ? -1.0 : 1.0}, eta, d)) return false;
  } else {
    const double R = s.radius;
    // With c = p.(p - 2C) and b = (p - C).d for the centre C = (0, 0, R),
    // the hits are at t = -b -+ sqrt(b^2 - c) (d is unit).
    const double zc = p.z - R;
    const double b = p.x * d.x + p.y * d.y + zc * d.z;
    const double c = p.x * p.x + p.y * p.y + p.z * (p.z - 2.0 * R);
    const double disc = b * b - c;
    if (!(disc >= 0.0)) return false;
    const double root = std::sqrt(disc);
    // The first crossing of the cap around the vertex (not the far
    // hemisphere), and the sign that turns (hit - C) / R into the unit
    // normal facing the ray: + on the nearer root, - on the farther.
    double t = -b - root, normalScale = s.absInvRadius;
    if (!(t >= -1e-9 && (zc + d.z * t) * R < 0.0)) {
      t = -b + root, normalScale = -s.absInvRadius;
      if (!(t >= -1e-9 && (zc + d.z * t) * R < 0.0)) return false;
    }
    const Vec3d hit = p + d * t;
    if (hit.x * hit.x + hit.y * hit.y > s.apertureRadius2) return false;
    o = {hit.x, hit.y, hit.z + s.z};
    if (path) path->push_back(o);
    if (eta == 0.0) return true;
    // Snell's law with cos i = |(hit - C).d| / |R| = sqrt(disc) / |R|.
    const double cos2I = std::min(1.0, disc * s.invRadius2);
    const double sin2T = eta * eta * (1.0 - cos2I);
    if (sin2T >= 1.0) return false;  // total internal reflection
    const double cosI = root * s.absInvRadius;
    const double cosT = std::sqrt(1.0 - sin2T);
    d = d * eta + Vec3d{hit.x, hit.y, hit.z - R} * (normalScale * (eta * cosI - cosT));
  }
  return kFromFilm ? d.z < 0.0 : d.z > 0.0;  // false: turned back
}

namespace {

template <bool kFromFilm>
bool validInput(const LensRay& ray) {
  return isFinite(ray.origin) && isFinite(ray.direction) &&
         (kFromFilm ? ray.direction.z < 0.0 : ray.direction.z > 0.0);
}

std::optional<LensRay> finished(const Vec3d& o, const Vec3d& d, double transmittance = 1.0) {
  if (!isFinite(o) || !isFinite(d)) return std::nullopt;
  return LensRay{o, normalize(d), transmittance};
}

// The Fresnel transmittance of a refraction from unit direction `in` to unit
// `out` with index ratio eta = n1 / n2: out - eta in is along the normal
// (Snell's law in vector form), which gives both angles' cosines.
double refractionTransmittance(Coating coating, const Vec3d& in, const Vec3d& out, double n1, double n2,
                               double wavelengthNm) {
  const Vec3d normal = normalize(out - in * (n1 / n2));
  const double cos1 = std::min(1.0, std::abs(dot(normal, in))),
               cos2 = std::min(1.0, std::abs(dot(normal, out)));
  return surfaceTransmittance(coating, n1, n2, cos1, cos2, wavelengthNm);
}

}  // namespace

// kCoated: the system models coatings (coating_ is set); a separate
// instantiation so that the lossless trace carries no Fresnel bookkeeping.
// Crossings [first, last) of the trace's order (from the film: the last
// surface first); false when blocked.
template <bool kFromFilm, bool kCoated>
inline bool LensSystem::cross(Vec3d& o, Vec3d& d, double& transmittance, int first, int last,
                              double wavelengthNm, std::vector<Vec3d>* path) const {
  const bool dLine = wavelengthNm == kWavelengthDNm;
  const int count = surfaceCount();
  const TraceSurface* const surfaces = surfaces_.data();
  // Index on the side the ray comes from, carried along for dispersion.
  double nFrom = 1.0;
  if (!dLine) {
    if constexpr (kFromFilm)
      nFrom = surfaces[count - 1 - first].after.index(wavelengthNm);
    else
      nFrom = first > 0 ? surfaces[first - 1].after.index(wavelengthNm) : 1.0;
  }
  for (int k = first; k < last; ++k) {
    const int i = kFromFilm ? count - 1 - k : k;
    const TraceSurface& s = surfaces[i];
    double eta = 0.0, n1 = 1.0, n2 = 1.0;
    if (dLine) {
      if (s.refracts) eta = kFromFilm ? s.etaFromFilm : s.etaFromScene;
      if constexpr (kCoated) {
        const double before = i > 0 ? surfaces[i - 1].ndAfter : 1.0;
        n1 = kFromFilm ? s.ndAfter : before;
        n2 = kFromFilm ? before : s.ndAfter;
      }
    } else {
      n1 = nFrom;
      nFrom =
          kFromFilm ? (i > 0 ? surfaces[i - 1].after.index(wavelengthNm) : 1.0) : s.after.index(wavelengthNm);
      n2 = nFrom;
      if (!s.isStop && n1 != nFrom) eta = n1 / nFrom;
    }
    const Vec3d in = d;
    if (!step<kFromFilm>(s, eta, o, d, path)) return false;
    if constexpr (kCoated)
      if (eta != 0.0) transmittance *= refractionTransmittance(*coating_, in, d, n1, n2, wavelengthNm);
  }
  return true;
}

template <bool kFromFilm, bool kCoated>
std::optional<LensRay> LensSystem::trace(const LensRay& ray, double wavelengthNm,
                                         std::vector<Vec3d>* path) const {
  if (!validInput<kFromFilm>(ray)) return std::nullopt;
  Vec3d o = ray.origin;
  Vec3d d = normalize(ray.direction);
  double transmittance = ray.transmittance;
  if (!cross<kFromFilm, kCoated>(o, d, transmittance, 0, surfaceCount(), wavelengthNm, path))
    return std::nullopt;
  return finished(o, d, transmittance);
}

Vec3d LensSystem::facingNormal(const TraceSurface& s, const Vec3d& hit, const Vec3d& d) {
  const Vec3d local{hit.x, hit.y, hit.z - s.z};
  Vec3d n = s.asphere         ? asphereNormal(*s.asphere, local)
            : s.radius == 0.0 ? Vec3d{0.0, 0.0, 1.0}
                              : Vec3d{local.x, local.y, local.z - s.radius} * s.invRadius;
  n = normalize(n);
  return dot(n, d) > 0.0 ? -n : n;
}

std::optional<LensRay> LensSystem::traceGhostFromScene(const LensRay& ray, int first, int second,
                                                       double wavelengthNm, std::vector<Vec3d>* path) const {
  const int count = surfaceCount();
  if (!(0 <= second && second < first && first < count) || !validInput<false>(ray)) return std::nullopt;
  const bool dLine = wavelengthNm == kWavelengthDNm;
  const auto indexAfter = [&](int i) {
    if (i < 0) return 1.0;
    return dLine ? surfaces_[std::size_t(i)].ndAfter : surfaces_[std::size_t(i)].after.index(wavelengthNm);
  };
  const Coating reflectionCoating = coating_.value_or(Coating::None);
  Vec3d o = ray.origin, d = normalize(ray.direction);
  double transmittance = ray.transmittance;
  // Surface i met travelling toward +z (forward) or -z: the indices on the
  // side the ray comes from and on the other.
  const auto sides = [&](int i, bool forward) {
    const double before = indexAfter(i - 1), after = indexAfter(i);
    return forward ? std::pair{before, after} : std::pair{after, before};
  };
  const auto hit = [&](int i, bool forward, double eta) {
    const TraceSurface& s = surfaces_[std::size_t(i)];
    return forward ? step<false>(s, eta, o, d, path) : step<true>(s, eta, o, d, path);
  };
  const auto cross = [&](int i, bool forward) {
    const auto [n1, n2] = sides(i, forward);
    const double eta = surfaces_[std::size_t(i)].isStop || n1 == n2 ? 0.0 : n1 / n2;
    const Vec3d in = d;
    if (!hit(i, forward, eta)) return false;
    if (coating_ && eta != 0.0)
      transmittance *= refractionTransmittance(*coating_, in, d, n1, n2, wavelengthNm);
    return true;
  };
  const auto reflect = [&](int i, bool forward) {
    if (!hit(i, forward, 0.0)) return false;
    const Vec3d n = facingNormal(surfaces_[std::size_t(i)], o, d);
    const double cosI = std::min(1.0, -dot(n, d));
    // The Fresnel reflectance 1 - T, with the refraction angle the surface
    // would have given (1 under total internal reflection).
    const auto [n1, n2] = sides(i, forward);
    const double sin2T = (n1 / n2) * (n1 / n2) * std::max(0.0, 1.0 - cosI * cosI);
    transmittance *= sin2T >= 1.0 ? 1.0
                                  : 1.0 - surfaceTransmittance(reflectionCoating, n1, n2, cosI,
                                                               std::sqrt(1.0 - sin2T), wavelengthNm);
    d = d + n * (2.0 * cosI);
    return true;
  };
  for (int i = 0; i < first; ++i)
    if (!cross(i, true)) return std::nullopt;
  if (!reflect(first, true)) return std::nullopt;
  for (int i = first - 1; i > second; --i)
    if (!cross(i, false)) return std::nullopt;
  if (!reflect(second, false)) return std::nullopt;
  for (int i = second + 1; i < count; ++i)
    if (!cross(i, true)) return std::nullopt;
  return finished(o, d, transmittance);
}

// The barrel: a ray outside a surface's clear aperture (or missing the
// surface) meets the mount, modelled as the annulus in the plane of the
// surface's rim (rimZ) around the aperture, a Lambertian reflector of albedo
// barrelReflectance facing the ray. The stop's blades are black.
LensSystem::FlareTrace LensSystem::flareTrace(const LensRay& ray, bool fromFilm, const FlareOptions& options,
                                              const std::function<double()>& random, double wavelengthNm,
                                              std::vector<Vec3d>* path) const {
  FlareTrace result;
  if (options.ghost && (fromFilm || options.barrelReflectance > 0.0))
    throw std::invalid_argument("flareTrace: a ghost is made from the scene, without the barrel");
  if (!(fromFilm ? validInput<true>(ray) : validInput<false>(ray))) return result;
  const int count = surfaceCount();
  const bool dLine = wavelengthNm == kWavelengthDNm;
  const auto indexAfter = [&](int i) {
    if (i < 0) return 1.0;
    return dLine ? surfaces_[std::size_t(i)].ndAfter : surfaces_[std::size_t(i)].after.index(wavelengthNm);
  };
  const Coating coating = coating_.value_or(Coating::None);
  Vec3d o = ray.origin, d = normalize(ray.direction);
  double weight = ray.transmittance;
  const auto bounce = [&](int surface, bool barrel) {
    if (result.reflections < FlareTrace::kRecorded)
      result.bounces[std::size_t(result.reflections)] = {surface, barrel};
    ++result.reflections;
  };
  const auto absorb = [&] {
    result.end = FlareTrace::End::Blocked;
    result.ray = {o, d, weight};
    result.absorbed += weight;
    return result;
  };
  int i = fromFilm ? count - 1 : 0;
  bool towardScene = fromFilm;
  while (true) {
    if (i < 0 || i >= count) {
      const std::optional<LensRay> out = finished(o, d, weight);
      if (!out) return absorb();
      result.end = i < 0 ? FlareTrace::End::Scene : FlareTrace::End::Film;
      result.ray = *out;
      return result;
    }
    const TraceSurface& s = surfaces_[std::size_t(i)];
    const double before = indexAfter(i - 1), after = indexAfter(i);
    const double n1 = towardScene ? after : before, n2 = towardScene ? before : after;
    // Hit the surface (its aperture blocks), then bend by hand.
    const Vec3d o0 = o, d0 = d;
    const bool reached = towardScene ? step<true>(s, 0.0, o, d, path) : step<false>(s, 0.0, o, d, path);
    if (!reached) {
      o = o0, d = d0;
      const double t = (s.rimZ - o.z) / d.z;
      if (s.isStop || !(options.barrelReflectance > 0.0) || !(t >= 0.0)) return absorb();
      o = o + d * t;
      if (path) path->push_back(o);
      if (result.reflections >= options.maxReflections) {
        // The scattered part is beyond the reflections allowed.
        result.truncated += weight * options.barrelReflectance;
        weight *= 1.0 - options.barrelReflectance;
        return absorb();
      }
      if (random() >= options.barrelReflectance) return absorb();
      // Cosine-distributed about the rim's normal, back the way it came.
      const double u = random(), phi = 2.0 * kPi * random(), r = std::sqrt(u);
      const double back = towardScene ? 1.0 : -1.0;
      d = {r * std::cos(phi), r * std::sin(phi), back * std::sqrt(std::max(0.0, 1.0 - u))};
      if (d.z == 0.0) return absorb();
      towardScene = !towardScene;
      bounce(i, true);
      i += towardScene ? -1 : 1;
      continue;
    }
    if (s.isStop && options.stop) {
      const double t = std::clamp(options.stop(o.x, o.y), 0.0, 1.0);
      result.absorbed += weight * (1.0 - t);
      weight *= t;
      if (!(weight > 0.0)) return absorb();
    }
    if (!s.isStop && n1 != n2) {
      const Vec3d n = facingNormal(s, o, d);
      const double cosI = std::min(1.0, -dot(n, d));
      Vec3d refracted;
      const bool passes = refract(d, n, n1, n2, refracted);
      const double r = passes ? 1.0 - surfaceTransmittance(coating, n1, n2, cosI,
                                                           std::min(1.0, -dot(n, refracted)), wavelengthNm)
                              : 1.0;
      // Reflect or refract, and the weight that keeps the expected flux.
      bool reflect = false;
      if (options.ghost) {
        reflect = (!towardScene && result.reflections == 0 && i == options.ghost->first) ||
                  (towardScene && result.reflections == 1 && i == options.ghost->second);
        weight *= reflect ? r : 1.0 - r;
      } else {
        const bool mayReflect = result.reflections < options.maxReflections;
        const double q = mayReflect && options.reflectionBoost > 1.0
                             ? std::max(r, std::min(0.5, options.reflectionBoost * r))
                             : r;
        reflect = mayReflect && random() < q;
        if (reflect) {
          if (q != r) weight *= r / q;
        } else if (!mayReflect) {
          // Made to refract: the reflected part R is dropped (all of it
          // under total internal reflection).
          result.truncated += weight * r;
          weight *= 1.0 - r;
        } else if (q != r) {
          weight *= (1.0 - r) / (1.0 - q);
        }
      }
      if (reflect) {
        d = d + n * (2.0 * cosI);
        towardScene = !towardScene;
        bounce(i, false);
      } else {
        if (!passes) {
          result.end = FlareTrace::End::Blocked;
          result.ray = {o, d, 0.0};
          return result;
        }
        d = refracted;
      }
    }
    i += towardScene ? -1 : 1;
  }
}

void LensSystem::traceFromFilm(std::span<const LensRay> rays, std::span<std::optional<LensRay>> out) const {
  if (out.size() != rays.size()) throw std::invalid_argument("traceFromFilm: as many outputs as rays");
  // Coatings: the one-ray trace, which carries the transmittance.
  if (coating_) {
    for (std::size_t i = 0; i < rays.size(); ++i)
      out[i] = trace<true, true>(rays[i], kWavelengthDNm, nullptr);
    return;
  }
  // The vector step knows only spheres: aspheric lenses take the one-lane
  // loop below, which calls the same step() as the one-ray trace.
  if (trace_lanes::available() && !hasAspheres_) return traceFromFilmVectorized(rays, {}, out);
  const int count = surfaceCount();
  const TraceSurface* const surfaces = surfaces_.data();
  for (std::size_t first = 0; first < rays.size(); first += kTraceLanes) {
    const std::size_t lanes = std::min(kTraceLanes, rays.size() - first);
    std::array<Vec3d, kTraceLanes> o, d;
    std::array<bool, kTraceLanes> alive{};
    for (std::size_t l = 0; l < lanes; ++l) {
      const LensRay& r = rays[first + l];
      alive[l] = validInput<true>(r);
      o[l] = r.origin;
      d[l] = alive[l] ? normalize(r.direction) : Vec3d{};
    }
    // Surface by surface, every lane: the lanes' dependency chains are
    // independent, so the CPU overlaps them.
    for (int i = count - 1; i >= 0; --i) {
      const TraceSurface& s = surfaces[i];
      const double eta = s.refracts ? s.etaFromFilm : 0.0;
      for (std::size_t l = 0; l < lanes; ++l)
        if (alive[l]) alive[l] = step<true>(s, eta, o[l], d[l], nullptr);
    }
    for (std::size_t l = 0; l < lanes; ++l)
      out[first + l] = alive[l] ? finished(o[l], d[l], rays[first + l].transmittance) : std::nullopt;
  }
}

void LensSystem::traceFromFilm(std::span<const LensRay> rays, std::span<const double> wavelengthsNm,
                               std::span<std::optional<LensRay>> out) const {
  if (out.size() != rays.size() || wavelengthsNm.size() != rays.size())
    throw std::invalid_argument("traceFromFilm: as many outputs and wavelengths as rays");
  // Coatings: the one-ray trace, which carries the transmittance.
  if (coating_) {
    for (std::size_t i = 0; i < rays.size(); ++i)
      out[i] = trace<true, true>(rays[i], wavelengthsNm[i], nullptr);
    return;
  }
  if (trace_lanes::available() && !hasAspheres_) return traceFromFilmVectorized(rays, wavelengthsNm, out);
  for (std::size_t i = 0; i < rays.size(); ++i)
    out[i] = trace<true, false>(rays[i], wavelengthsNm[i], nullptr);
}

// The same trace with spherical surfaces stepped in vector registers
// (trace_lanes); flat ones (the stop, windows) one lane at a time. With
// wavelengths, each lane's index ratios are computed as trace() does.
void LensSystem::traceFromFilmVectorized(std::span<const LensRay> rays, std::span<const double> wavelengthsNm,
                                         std::span<std::optional<LensRay>> out) const {
  static_assert(kTraceLanes == trace_lanes::kLanes);
  const std::vector<trace_lanes::Sphere>& spheres = spheres_;
  // Zeroed once, not per batch: a batch fills its lanes, and those past its
  // end stay dead (their values, zeros or an earlier batch's, are never read).
  trace_lanes::Lanes L;
  for (std::size_t first = 0; first < rays.size(); first += kTraceLanes) {
    const std::size_t lanes = std::min(kTraceLanes, rays.size() - first);
    for (std::size_t l = 0; l < lanes; ++l) {
      const LensRay& r = rays[first + l];
      L.ox[l] = r.origin.x, L.oy[l] = r.origin.y, L.oz[l] = r.origin.z;
      L.dx[l] = r.direction.x, L.dy[l] = r.direction.y, L.dz[l] = r.direction.z;
      L.alive[l] = ~0ll;
    }
    std::fill(L.alive.begin() + std::ptrdiff_t(lanes), L.alive.end(), 0ll);
    trace_lanes::start(L);  // validInput<true> and normalize
    // Per lane: the index on the film side of the next surface (trace()'s nFrom).
    const bool spectral = !wavelengthsNm.empty();
    std::array<double, kTraceLanes> wavelength{}, nFrom{}, eta{};
    std::array<bool, kTraceLanes> dLine{};
    if (spectral)
      for (std::size_t l = 0; l < lanes; ++l) {
        wavelength[l] = wavelengthsNm[first + l];
        dLine[l] = wavelength[l] == kWavelengthDNm;
        nFrom[l] = dLine[l] ? 1.0 : surfaces_.back().after.index(wavelength[l]);
      }
    for (int i = surfaceCount() - 1; i >= 0; --i) {
      const TraceSurface& s = surfaces_[i];
      if (spectral)
        for (std::size_t l = 0; l < kTraceLanes; ++l) {
          if (l >= lanes || dLine[l]) {
            eta[l] = spheres[i].eta;
            continue;
          }
          const double n1 = nFrom[l];
          nFrom[l] = i > 0 ? surfaces_[i - 1].after.index(wavelength[l]) : 1.0;
          eta[l] = !s.isStop && n1 != nFrom[l] ? n1 / nFrom[l] : 0.0;
        }
      if (s.radius != 0.0) {
        if (spectral)
          trace_lanes::sphereStep(spheres[i], eta, L);
        else
          trace_lanes::sphereStep(spheres[i], L);
        continue;
      }
      // A flat surface that bends no lane (the stop; at the d line, any
      // between equal indices) in vector registers too.
      if (s.isStop || (!spectral && !s.refracts)) {
        trace_lanes::planeStep(spheres[i], L);
        continue;
      }
      for (std::size_t l = 0; l < lanes; ++l) {
        if (!L.alive[l]) continue;
        Vec3d o{L.ox[l], L.oy[l], L.oz[l]}, d{L.dx[l], L.dy[l], L.dz[l]};
        L.alive[l] = step<true>(s, spectral ? eta[l] : spheres[i].eta, o, d, nullptr) ? ~0ll : 0;
        L.ox[l] = o.x, L.oy[l] = o.y, L.oz[l] = o.z;
        L.dx[l] = d.x, L.dy[l] = d.y, L.dz[l] = d.z;
      }
    }
    trace_lanes::finish(L);  // finished(): finite, then the direction normalised
    for (std::size_t l = 0; l < lanes; ++l)
      out[first + l] =
          L.alive[l]
              ? std::optional<LensRay>(LensRay{
                    {L.ox[l], L.oy[l], L.oz[l]}, {L.dx[l], L.dy[l], L.dz[l]}, rays[first + l].transmittance})
              : std::nullopt;
  }
}

std::optional<LensRay> LensSystem::traceFromFilm(const LensRay& ray, double wavelengthNm,
                                                 std::vector<Vec3d>* path) const {
  return coating_ ? trace<true, true>(ray, wavelengthNm, path) : trace<true, false>(ray, wavelengthNm, path);
}

std::optional<LensRay> LensSystem::traceFromScene(const LensRay& ray, double wavelengthNm,
                                                  std::vector<Vec3d>* path) const {
  return coating_ ? trace<false, true>(ray, wavelengthNm, path)
                  : trace<false, false>(ray, wavelengthNm, path);
}

// Coatings change only the transmittance: the uncoated trace's hits are the
// coated one's, bit for bit.
std::optional<LensSystem::PausedTrace> LensSystem::traceFromSceneTo(const LensRay& ray, int surface,
                                                                    double wavelengthNm,
                                                                    std::vector<Vec3d>* path) const {
  if (surface < 0 || surface >= surfaceCount() || !validInput<false>(ray)) return std::nullopt;
  PausedTrace t{ray.origin, normalize(ray.direction), surface + 1};
  double transmittance = 1.0;
  if (!cross<false, false>(t.origin, t.direction, transmittance, 0, t.crossed, wavelengthNm, path))
    return std::nullopt;
  return t;
}

std::optional<LensRay> LensSystem::resumeFromScene(const PausedTrace& paused, double wavelengthNm) const {
  if (paused.crossed < 0 || paused.crossed > surfaceCount()) return std::nullopt;
  Vec3d o = paused.origin, d = paused.direction;
  double transmittance = 1.0;
  if (!cross<false, false>(o, d, transmittance, paused.crossed, surfaceCount(), wavelengthNm, nullptr))
    return std::nullopt;
  return finished(o, d, transmittance);
}

bool LensSystem::rimsHold(std::span<const Vec3d> hits) const {
  if (hits.size() > surfaces_.size()) return false;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const TraceSurface& s = surfaces_[i];
    // An asphere's hit is found within its own rim (optics/asphere.h).
    if (!s.asphere && hits[i].x * hits[i].x + hits[i].y * hits[i].y > s.apertureRadius2) return false;
  }
  return true;
}

std::optional<Vec3d> LensSystem::hitFromFilm(const LensRay& ray, int surface, double wavelengthNm) const {
  if (surface < 0 || surface >= surfaceCount() || !validInput<true>(ray)) return std::nullopt;
  Vec3d o = ray.origin, d = normalize(ray.direction);
  double transmittance = 1.0;
  if (!cross<true, false>(o, d, transmittance, 0, surfaceCount() - surface, wavelengthNm, nullptr) ||
      !isFinite(o) || !isFinite(d))
    return std::nullopt;
  return o;
}

}  // namespace lensrt
