#include "camera/lens_camera.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "camera/film_mapping.h"
#include "core/constants.h"
#include "optics/chromatic.h"
#include "optics/focus.h"

namespace lensrt {

LensCamera::LensCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                       const LensPrescription& prescription, const LensCameraParams& params,
                       const Exposure& exposure, Warnings& warnings)
    : Camera(worldFromCamera, film),
      params_(params),
      exposure_(exposure),
      dispersion_(params.dispersion && hasDispersion(prescription)),
      movedFilm_(params.movements) {
  checkLensMovements(params.movements, film, "lens");
  const ParaxialData open = computeParaxial(prescription);
  double n = params.fNumber > 0.0 ? params.fNumber : open.fNumber;
  // A polygon of the f-number's area needs a round stop as wide as its corners.
  const double widen = polygonCircumradiusFactor(params.aperture.blades);
  LensPrescription stopped = stopDown(prescription, n / widen, warnings);
  lens_ = std::make_unique<LensSystem>(std::move(stopped), params.coatings);
  const ParaxialData& p = lens_->paraxial();
  fNumber_ = p.fNumber * widen;
  entrancePupilZ_ = p.entrancePupilZ;
  stopRadius_ = lens_->prescription().surfaces[p.stopIndex].apertureDiameter / 2.0;
  if (params.aperture.blades) polygon_.emplace(stopRadius_ / widen, params.aperture);
  filmZ_ = lens_->rearZ() + focusFilmDistance(*lens_, params.focusMetres * 1000.0);
  if (params.diffraction) {
    // The stop in units of its radius (the blades' corners, the mask's
    // scale), imaged to the entrance pupil, whose radius that unit becomes.
    std::function<double(double, double)> stop;
    if (polygon_ || params.mask)
      stop = [polygon = polygon_, mask = params.mask, radius = stopRadius_](double x, double y) {
        const Vec2d at{x * radius, y * radius};
        if (polygon && !polygon->contains(at)) return 0.0;
        return mask ? mask->transmittance(at, radius) : 1.0;
      };
    setDiffraction(std::make_shared<const StopDiffraction>(stop, p.entrancePupilDiameter / 2.0));
  }
  chiefRays_ = std::make_unique<const ChiefRays>(*lens_, filmZ_);
  if (!params.movements.any()) {
    bounds_ = std::make_unique<ExitPupilBounds>(*lens_, filmZ_, sensorHalfDiagonalMm(film) * (1.0 + 1e-6),
                                                params.pupilIntervals);
  } else {
    // Out to the farthest film point the moved frame reaches, for every
    // depth a tilted film's points take (ExitPupilBounds' slab): bounds
    // that hold for each point where it actually lies.
    const MovedFilm::DepthRange depth = movedFilm_.depthRange(film);
    if (!(filmZ_ + depth.min > lens_->rearZ()))
      throw std::invalid_argument("lens: the tilted film reaches the lens's rear vertex");
    bounds_ = std::make_unique<ExitPupilBounds>(*lens_, filmZ_, movedFilm_.maxRadius(film) * (1.0 + 1e-6),
                                                params.pupilIntervals, FilmDepthRange{depth.min, depth.max});
  }
  scale_ = lensrt::exposureScale(exposure, fNumber_);
  if (params.flareReflections) {
    flareOptions_.maxReflections = *params.flareReflections;
    flareOptions_.barrelReflectance = params.barrelReflectance;
    // The same stop as traceLens(): the polygon, then the mask.
    if (polygon_ || params.mask)
      flareOptions_.stop = [polygon = polygon_, mask = params.mask, radius = stopRadius_](double x,
                                                                                          double y) {
        if (polygon && !polygon->contains({x, y})) return 0.0;
        return mask ? mask->transmittance({x, y}, radius) : 1.0;
      };
  }
}

namespace {

std::string barrelText(double reflectance) {
  char buf[40];
  std::snprintf(buf, sizeof buf, " barrel=%.9g", reflectance);
  return buf;
}

}  // namespace

std::string LensCamera::describe() const {
  char buf[240];
  std::snprintf(buf, sizeof buf, "lens %s f=%.4gmm f/%.3g focus=%s aperture=%s",
                lens_->prescription().name.c_str(), lens_->paraxial().efl, fNumber_,
                focusText(params_.focusMetres).c_str(), lensrt::describe(params_.aperture).c_str());
  // Part of the render's identity (merge, resume): on and off differ, and so do coatings.
  return std::string(buf) + (dispersion_ ? " dispersion=on" : "") +
         (params_.flareReflections ? " flare=" + std::to_string(*params_.flareReflections) : std::string()) +
         (params_.flareReflections && params_.barrelReflectance > 0.0 ? barrelText(params_.barrelReflectance)
                                                                      : std::string()) +
         (params_.coatings ? " coatings=" + coatingName(*params_.coatings) : std::string()) +
         (params_.mask ? " mask=" + params_.mask->describe() : std::string()) +
         (params_.diffraction ? " diffraction=on" : "") + params_.movements.describe();
}

CameraInfo LensCamera::info() const {
  CameraInfo i{"lens",
               lens_->prescription().name,
               fNumber_,
               params_.focusMetres,
               lens_->paraxial().efl,
               lensrt::describe(exposure_),
               dispersion_,
               params_.coatings ? coatingName(*params_.coatings) : std::string()};
  i.movements = params_.movements;
  i.entrancePupilOffsetMm = filmZ_ - entrancePupilZ_;  // lens space: +z toward the film
  return i;
}

namespace {

// E/L integrand over the rear-vertex plane, parallel to the film:
// cos(th_film) cos(th_plane) / d^2 = dz^2 / d^4.
double irradianceIntegrand(const Vec3d& filmPoint, const Vec3d& pupilPoint) {
  const double dz = filmPoint.z - pupilPoint.z;
  const double d2 = lengthSquared(pupilPoint - filmPoint);
  return dz * dz / (d2 * d2);
}

}  // namespace

double LensCamera::integrand(const Vec3d& filmPoint, const Vec3d& pupilPoint) const {
  if (!params_.movements.tilted()) return irradianceIntegrand(filmPoint, pupilPoint);
  // cos(th_film) against the tilted film's normal: n.(q - p) dz / d^4.
  const Vec3d d = pupilPoint - filmPoint;
  const double d2 = lengthSquared(d);
  return dot(movedFilm_.normal(), d) * -d.z / (d2 * d2);
}

std::optional<LensRay> LensCamera::traceLens(const LensRay& in, double wavelengthNm) const {
  if (!polygon_ && !params_.mask) return lens_->traceFromFilm(in, wavelengthNm);
  std::vector<Vec3d> path;
  path.reserve(lens_->surfaceCount());
  std::optional<LensRay> out = lens_->traceFromFilm(in, wavelengthNm, &path);
  if (!out) return out;
  // The path runs from the rear surface to the front one.
  const Vec3d& hit = path.at(lens_->surfaceCount() - 1 - lens_->paraxial().stopIndex);
  if (polygon_ && !polygon_->contains({hit.x, hit.y})) return std::nullopt;
  if (params_.mask) {
    const double t = params_.mask->transmittance({hit.x, hit.y}, stopRadius_);
    if (!(t > 0.0)) return std::nullopt;
    out->transmittance *= t;
  }
  return out;
}

std::optional<Ray> LensCamera::traceThrough(const Vec2f& raster, const Vec2d& pupilPoint,
                                            double wavelengthNm) const {
  const Vec3d p = filmPointMm(raster);
  const std::optional<CameraRay> r =
      cameraRay(traceLens({p, Vec3d{pupilPoint.x, pupilPoint.y, bounds_->planeZ()} - p}, wavelengthNm), 1.0);
  if (!r) return std::nullopt;
  return r->ray;
}

Vec3d LensCamera::filmPointMm(const Vec2f& raster) const {
  const Vec2d up = uprightSensorPointMm(film(), raster);
  if (params_.movements.any()) return Vec3d{0.0, 0.0, filmZ_} + movedFilm_.offset(up);
  return {-up.x, -up.y, filmZ_};  // the inverted real image
}

Vec3d LensCamera::filmHitMm(const LensRay& t) const {
  if (!params_.movements.any()) {
    const double s = (filmZ_ - t.origin.z) / t.direction.z;
    return {t.origin.x + s * t.direction.x, t.origin.y + s * t.direction.y, filmZ_};
  }
  // The moved film's plane through (0, 0, filmZ) with its normal.
  const Vec3d& n = movedFilm_.normal();
  const Vec3d toPivot = Vec3d{0.0, 0.0, filmZ_} - t.origin;
  const double s = dot(n, toPivot) / dot(n, t.direction);
  return t.origin + t.direction * s;
}

Vec2d LensCamera::rasterOfFilmHit(const LensRay& t) const {
  return rasterOfFilmPoint(filmHitMm(t));
}

Vec2d LensCamera::rasterOfFilmPoint(const Vec3d& hit) const {
  if (!params_.movements.any()) return rasterOfUprightSensorPointMm(film(), {-hit.x, -hit.y});
  return rasterOfUprightSensorPointMm(film(), movedFilm_.upright(hit - Vec3d{0.0, 0.0, filmZ_}));
}

LensCamera::PupilRay LensCamera::pupilRay(const Vec3d& p, const std::optional<PupilSample>& ps) const {
  if (!ps) return {{p, Vec3d{}}, 0.0};
  return {{p, ps->point - p}, scale_ * integrand(p, ps->point) / ps->pdf};
}

// Lens space (mm, from the front vertex) to camera space (metres, from the entrance pupil).
std::optional<CameraRay> LensCamera::cameraRay(const std::optional<LensRay>& out, double weight) const {
  if (!out) return std::nullopt;
  const Vec3d o = Vec3d{out->origin.x, out->origin.y, out->origin.z - entrancePupilZ_} * 1e-3;
  return CameraRay{Ray{Vec3f(o), Vec3f(out->direction)}, float(weight * out->transmittance)};
}

namespace {

// The flare trace's choices from the sample's own numbers: a stream keyed by
// the bits of its film, lens and wavelength values (deterministic, and
// independent of the sampler's dimensions, which stay as without flare).
class SampleStream {
 public:
  explicit SampleStream(const CameraSample& s) {
    for (const float v : {s.film.x, s.film.y, s.lens.x, s.lens.y, s.wavelengthNm})
      state_ = mix(state_ ^ std::bit_cast<std::uint32_t>(v));
  }
  double operator()() { return double(mix(state_ += 0x9e3779b97f4a7c15ULL) >> 11) * 0x1.0p-53; }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t state_ = 0x666c617265ULL;
};

}  // namespace

std::optional<CameraRay> LensCamera::flareRay(const CameraSample& s) const {
  const Vec3d p = filmPointMm(s.film);
  // Half the samples from the bounds, half uniform over a disc 20% wider
  // than the rear element (a curved rear surface reaches past its rim's
  // radius on the plane); the pdf is the mixture's, so both count exactly.
  const double discRadius = 1.2 * lens_->rearApertureRadius();
  Vec2d point;
  if (s.lens.x < 0.5f) {
    const std::optional<PupilSample> ps = bounds_->sample({p.x, p.y}, {2.0 * s.lens.x, s.lens.y});
    if (!ps) return std::nullopt;
    point = {ps->point.x, ps->point.y};
  } else {
    const double r = discRadius * std::sqrt(2.0 * s.lens.x - 1.0), phi = 2.0 * kPi * s.lens.y;
    point = {r * std::cos(phi), r * std::sin(phi)};
  }
  const double inDisc = point.x * point.x + point.y * point.y <= discRadius * discRadius ? 1.0 : 0.0;
  const double pdf = 0.5 * bounds_->pdf({p.x, p.y}, point) + 0.5 * inDisc / (kPi * discRadius * discRadius);
  if (!(pdf > 0.0)) return std::nullopt;
  const Vec3d target{point.x, point.y, bounds_->planeZ()};
  const double weight = scale_ * integrand(p, target) / pdf;
  const double wavelength = tracesWavelengths() ? double(s.wavelengthNm) : kWavelengthDNm;
  SampleStream random(s);
  const LensSystem::FlareTrace t =
      lens_->traceFromFilmWithFlare({p, target - p}, flareOptions_, random, wavelength);
  if (t.end != LensSystem::FlareTrace::End::Scene) return std::nullopt;
  std::optional<CameraRay> out = cameraRay(t.ray, weight);
  if (out) out->lensReflected = t.reflections > 0;
  return out;
}

std::optional<CameraRay> LensCamera::generateCameraSpaceRay(const CameraSample& s) const {
  if (params_.flareReflections) return flareRay(s);
  const Vec3d p = filmPointMm(s.film);
  const std::optional<PupilSample> pupil = bounds_->sample({p.x, p.y}, {s.lens.x, s.lens.y});
  const PupilRay pr = pupilRay(p, pupil);
  if (pr.weight == 0.0) return std::nullopt;
  const double wavelength = dispersion_ ? double(s.wavelengthNm) : kWavelengthDNm;
  const std::optional<LensRay> out = traceLens(pr.ray, wavelength);
  std::optional<CameraRay> r = cameraRay(out, pr.weight);
  if (r && carriesLanes() && s.secondaryNm[0] > 0.0f) r->laneWeights = laneWeights(s, p, *pupil, *out);
  return r;
}

std::array<float, 4> LensCamera::laneWeights(const CameraSample& s, const Vec3d& filmPoint,
                                             const PupilSample& pupil, const LensRay& out) const {
  std::array<LaneTrace, 4> lanes;
  lanes[0] = {true, pupil.pdf / integrand(filmPoint, pupil.point), out.transmittance};
  const Vec2d pixel{std::floor(double(s.film.x)), std::floor(double(s.film.y))};
  // The same line from the scene side, from a millimetre out.
  const LensRay fromScene{out.origin + out.direction, out.direction * -1.0};
  for (std::size_t k = 1; k < lanes.size(); ++k) lanes[k] = traceLane(fromScene, s.secondaryNm[k - 1], pixel);
  return wavelengthLaneWeights(lanes);
}

LaneTrace LensCamera::traceLane(const LensRay& fromScene, double wavelengthNm, const Vec2d& pixel) const {
  std::optional<LensRay> back;
  if (!polygon_ && !params_.mask) {
    back = lens_->traceFromScene(fromScene, wavelengthNm);
  } else {
    // The stop as traceLens() takes it: the polygon, then the mask.
    std::vector<Vec3d> path;
    path.reserve(lens_->surfaceCount());
    back = lens_->traceFromScene(fromScene, wavelengthNm, &path);
    if (!back) return {};
    const Vec3d& hit = path.at(lens_->paraxial().stopIndex);  // the path runs from the front surface
    if (polygon_ && !polygon_->contains({hit.x, hit.y})) return {};
    if (params_.mask) {
      const double t = params_.mask->transmittance({hit.x, hit.y}, stopRadius_);
      if (!(t > 0.0)) return {};
      back->transmittance *= t;
    }
  }
  if (!back || !(back->direction.z > 0.0)) return {};
  const Vec3d filmPoint = filmHitMm(*back);
  const Vec2d raster = rasterOfFilmPoint(filmPoint);
  if (std::floor(raster.x) != pixel.x || std::floor(raster.y) != pixel.y) return {};
  const double s = (bounds_->planeZ() - back->origin.z) / back->direction.z;
  const Vec3d pupilPoint = back->origin + back->direction * s;
  const double pdf = bounds_->pdf({filmPoint.x, filmPoint.y}, {pupilPoint.x, pupilPoint.y});
  if (!(pdf > 0.0)) return {};
  return {true, pdf / integrand(filmPoint, pupilPoint), back->transmittance};
}

void LensCamera::generateCameraSpaceRays(std::span<const CameraSample> samples,
                                         std::span<std::optional<CameraRay>> out) const {
  if (polygon_ || params_.mask || params_.flareReflections)
    return Camera::generateCameraSpaceRays(samples, out);
  // In chunks: the bounds sample and the lens traces a chunk's rays together.
  // The chunk's arrays (20 KB) are kept per thread: on the stack, every call
  // zeroed them (their elements' default member initialisers), which cost
  // callgrind's count 200 instructions per ray at 4 spp.
  constexpr std::size_t kChunk = 4 * LensSystem::kTraceLanes;
  struct Chunk {
    std::array<Vec3d, kChunk> filmPoints;
    std::array<Vec2d, kChunk> filmXY, lensSamples;
    std::array<PupilSample, kChunk> pupil;
    std::array<LensRay, kChunk> rays;
    std::array<double, kChunk> weights, wavelengths;
    std::array<std::optional<LensRay>, kChunk> traced;
  };
  static thread_local Chunk chunk;
  auto& [filmPoints, filmXY, lensSamples, pupil, rays, weights, wavelengths, traced] = chunk;
  for (std::size_t first = 0; first < samples.size(); first += kChunk) {
    const std::size_t n = std::min(kChunk, samples.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      const CameraSample& s = samples[first + i];
      filmPoints[i] = filmPointMm(s.film);
      filmXY[i] = {filmPoints[i].x, filmPoints[i].y};
      lensSamples[i] = {s.lens.x, s.lens.y};
      wavelengths[i] = s.wavelengthNm;
    }
    bounds_->sample(std::span(filmXY).first(n), std::span(lensSamples).first(n), std::span(pupil).first(n));
    // pupilRay() on each sample, from its pupil sample (a pdf of 0: none).
    for (std::size_t i = 0; i < n; ++i) {
      const PupilRay pr =
          pupilRay(filmPoints[i], pupil[i].pdf == 0.0 ? std::nullopt : std::optional(pupil[i]));
      rays[i] = pr.ray;  // a zero direction fails the trace: blocked
      weights[i] = pr.weight;
    }
    if (dispersion_)
      lens_->traceFromFilm(std::span(rays).first(n), std::span(wavelengths).first(n),
                           std::span(traced).first(n));
    else
      lens_->traceFromFilm(std::span(rays).first(n), std::span(traced).first(n));
    const bool lanes = carriesLanes();
    for (std::size_t i = 0; i < n; ++i) {
      std::optional<CameraRay>& r = out[first + i] = cameraRay(traced[i], weights[i]);
      if (r && lanes && samples[first + i].secondaryNm[0] > 0.0f)
        r->laneWeights = laneWeights(samples[first + i], filmPoints[i], pupil[i], *traced[i]);
    }
  }
}

// The chief ray through the stop's centre (optics/chief_ray.h), traced at
// the wavelength when the camera traces each sample at its own (else the
// d line, as the render's rays are).
ProjectedPoint LensCamera::projectCameraPoint(const Vec3d& p, double wavelengthNm) const {
  return projectCameraPointHinted(p, wavelengthNm, nullptr);
}

ProjectedPoint LensCamera::projectCameraPointHinted(const Vec3d& p, double wavelengthNm,
                                                    ChiefRayHint* hint) const {
  const double wavelength = dispersion_ ? wavelengthNm : kWavelengthDNm;
  const ChiefRayImage image =
      chiefRays_->ofPoint({p.x * 1e3, p.y * 1e3, p.z * 1e3 + entrancePupilZ_}, wavelength, hint);
  if (image.status == ChiefRayStatus::Behind) return {image.film, Visibility::Behind};
  // The upright image is the film point's negative; a moved film meets the
  // chief ray's image-side line elsewhere.
  std::optional<Vec2d> upright = image.film * -1.0;
  if (params_.movements.any())
    upright = movedFilm_.uprightOfLine(
        image.film, {image.direction.x / image.direction.z, image.direction.y / image.direction.z});
  if (!upright) return {image.film, Visibility::Behind};
  const Vec2d raster = rasterOfUprightSensorPointMm(film(), *upright);
  if (image.status == ChiefRayStatus::Blocked) return {raster, Visibility::Blocked};
  return {raster, frameVisibility(film(), raster)};
}

ProjectedRay LensCamera::unprojectRaster(const Vec2d& raster, double wavelengthNm) const {
  const double wavelength = dispersion_ ? wavelengthNm : kWavelengthDNm;
  const ChiefRayToScene out =
      params_.movements.any()
          ? chiefRays_->ofFilmPoint(
                Vec3d{0.0, 0.0, filmZ_} + movedFilm_.offset(uprightSensorPointOfRaster(film(), raster)),
                wavelength)
          : chiefRays_->ofFilmPoint(uprightSensorPointOfRaster(film(), raster) * -1.0, wavelength);
  const Vec3d origin{out.ray.origin.x * 1e-3, out.ray.origin.y * 1e-3,
                     (out.ray.origin.z - entrancePupilZ_) * 1e-3};
  const Visibility visibility =
      out.status == ChiefRayStatus::Passes ? frameVisibility(film(), raster) : Visibility::Blocked;
  return {origin, out.ray.direction, visibility};
}

}  // namespace lensrt
