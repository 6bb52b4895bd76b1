#include "render/flare_light_pass.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/constants.h"
#include "core/frame.h"
#include "core/ray.h"
#include "optics/ghosts.h"
#include "render/environment.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/spectral_response.h"
#include "render/wavelengths.h"
#include "scene/render_scene.h"

namespace lensrt {

namespace {

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A chunk's stream: SplitMix64 from a key of (seed, source, chunk).
class ChunkStream {
 public:
  ChunkStream(std::uint64_t seed, std::uint64_t light, std::uint64_t chunk)
      : state_(mix(mix(mix(seed ^ 0x666c6172656c6974ULL) ^ light) ^ chunk)) {}
  double operator()() { return double(mix(state_ += 0x9e3779b97f4a7c15ULL) >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// A light as the lens sees it (lens space, mm): a point, or a direction
// from infinity, with what it sends toward the lens.
struct LensLight {
  bool atInfinity = false;
  Vec3d point;      // lens space, mm (a point light)
  Vec3d direction;  // unit, the way the light travels (directional)
  Rgb intensity;    // W/sr toward the lens (point), or irradiance across the beam (directional)
  Vec3f world;      // world space: the light's place, or the direction toward it (directional)
};

// Lens space (mm, from the front vertex; z toward the film) from camera
// space (metres, from the entrance pupil), and back.
struct LensFrame {
  const LensCamera& camera;
  Transform cameraFromWorld;
  Vec3d toLens(const Vec3d& cameraPoint) const {
    return {cameraPoint.x * 1e3, cameraPoint.y * 1e3, cameraPoint.z * 1e3 + camera.entrancePupilZ()};
  }
  Vec3f worldOf(const Vec3d& lens) const {
    return Vec3f(camera.worldFromCamera().point(
        Vec3d{lens.x * 1e-3, lens.y * 1e-3, (lens.z - camera.entrancePupilZ()) * 1e-3}));
  }
  Vec3d lensOf(const Vec3f& world) const { return toLens(cameraFromWorld.point(Vec3d(world))); }
};

std::optional<LensLight> lensLight(const LensFrame& frame, const PunctualLight& l) {
  const LensCamera& camera = frame.camera;
  LensLight out;
  if (l.type == PunctualLight::Type::Directional) {
    out.atInfinity = true;
    out.direction = normalize(frame.cameraFromWorld.vector(Vec3d(l.direction)));
    if (!(out.direction.z > 0.0)) return std::nullopt;  // the light travels away from the lens
    out.intensity = l.intensity;
    out.world = -l.direction;
    return out;
  }
  out.point = frame.lensOf(l.position);
  out.world = l.position;
  if (!(out.point.z < 0.0)) return std::nullopt;  // behind the front vertex
  // The spot's cone and the range window, toward the entrance pupil.
  const Vec3f toCamera = Vec3f(camera.worldFromCamera().point(Vec3d{0, 0, 0})) - l.position;
  const float distance = length(toCamera);
  float scale = rangeWindow(l, distance);
  if (l.type == PunctualLight::Type::Spot) scale *= spotAttenuation(l, toCamera / distance);
  if (!(scale > 0.0f)) return std::nullopt;
  out.intensity = l.intensity * scale;
  return out;
}

// The still emissive triangles' picking weights: each one's flux into the
// disc, estimated at its centroid (luminance x area x cosines / d^2), and
// for a triangle near the lens (closer than twice its size) the most a
// Lambertian emitter can send (pi sr of projected solid angle), so that no
// triangle that may send light in goes without paths (unbiased whatever the
// estimate). Zero only where no path could start: behind the front vertex
// plane, or single-sided and facing away from the whole disc.
std::vector<float> emitterWeights(const LensFrame& frame, const LightSet& lights, double discRadiusMm) {
  std::vector<float> weights(lights.emissiveTriangleCount(), 0.0f);
  const Vec3f centre = frame.worldOf({0, 0, 0});
  const Vec3f axis = normalize(frame.worldOf({0, 0, -1}) - centre);  // toward the scene
  const float discRadius = float(discRadiusMm * 1e-3);
  for (std::size_t t = 0; t < weights.size(); ++t) {
    const LightSet::EmissiveTriangle tri = lights.emissiveTriangle(t);
    if (!tri.still || !(tri.area > 0) || !(tri.luminance > 0)) continue;
    const std::array<Vec3f, 3> corners{tri.p0, tri.p0 + tri.e1, tri.p0 + tri.e2};
    if (std::all_of(corners.begin(), corners.end(), [&](const Vec3f& c) { return !(frame.lensOf(c).z < 0); }))
      continue;
    if (!tri.twoSided && dot(tri.normal, centre - tri.p0) < -discRadius) continue;
    const Vec3f q = (corners[0] + corners[1] + corners[2]) / 3.0f;
    float size = 0;
    for (const Vec3f& c : corners) size = std::max(size, length(c - q));
    const Vec3f toLens = centre - q;
    const float d = length(toLens);
    float g = kPiF;
    if (d > 2 * size) {
      const Vec3f w = toLens / d;
      const float cosE = std::max(0.05f, std::abs(dot(w, tri.normal))), cosL = std::max(0.05f, -dot(w, axis));
      g = std::min(kPiF, tri.area * cosE * cosL / (d * d));
    }
    weights[t] = tri.luminance * g;
  }
  return weights;
}

// A source of the pass: a punctual light, the still emitters together, the
// sun, or a lamp's light on the scene.
struct Source {
  enum class Kind { Punctual, Emitters, Sun, LitSurface };
  Kind kind = Kind::Punctual;
  LensLight light;  // Punctual
  std::uint64_t paths = 0;
  bool reflectedOnly = false;           // deposit only paths with a lens reflection
  const PunctualLight* lamp = nullptr;  // LitSurface
};

// A direction from a lamp (unit, world) uniform over its sphere, or a spot's
// over its outer cone, and its density (per steradian).
struct LampDirection {
  Vec3f direction;
  double pdf = 0;
};
LampDirection sampleLampDirection(const PunctualLight& lamp, double u1, double u2) {
  const bool spot = lamp.type == PunctualLight::Type::Spot;
  const double cosOuter = spot ? std::cos(double(std::clamp(lamp.outerConeAngle, 0.0f, kPiF))) : -1.0;
  const double cosTheta = 1.0 - u1 * (1.0 - cosOuter);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)), phi = 2.0 * kPi * u2;
  const Vec3f local{float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta)};
  const Vec3f axis = spot ? lamp.direction : Vec3f{0, 0, 1};
  return {normalize(Frame::fromNormal(axis).toWorld(local)), 1.0 / (2.0 * kPi * (1.0 - cosOuter))};
}

// What the surface at `hit` sends toward wo of a lamp's light arriving
// along -wi, in the units of the pass's lit-surface paths: the BSDF times
// the shading cosine, as a camera path's next-event estimate there takes it
// (with its conditions on the sides of the normals), times the geometric
// cosine toward wo (the area the disc sees) over the geometric cosine
// toward wi (the area the lamp's direction lights). `lambdas` drop their
// secondary wavelengths at a dispersive volume, as the camera path's do.
Spectrum litSurfaceReflection(const MaterialTable& materials, const SurfaceHit& hit, const Vec3f& wo,
                              const Vec3f& wi, SampledWavelengths& lambdas) {
  if (lambdas.spectral() && isDispersiveVolume(materials.material(hit.material)))
    lambdas.terminateSecondary();
  const ShadingPoint sp = evaluateMaterial(materials, hit, wo, lambdas);
  const GltfBsdf bsdf(sp.bsdf, sp.frame, sp.coatFrame, wo);
  const Vec3f& ng = sp.geometricNormal;
  if (!receivesLight(sp, bsdf, wi)) return Spectrum(0.0f);
  const float cosIn = std::abs(dot(wi, ng));
  if (!(cosIn > 1e-6f)) return Spectrum(0.0f);
  return bsdf.evalPdf(wo, wi).f * (std::abs(dot(wi, sp.frame.n)) * std::abs(dot(wo, ng)) / cosIn);
}

// A path's shadow ray: from its disc point (world) toward its source point,
// or toward a direction (distance infinite).
struct Shadow {
  Vec3f from, direction;
  float distance = kInfinityF;
};

// Where ghosts are not picked (ghostChoice: more than two reflections, or
// the barrel), the pass's paths reflect in the lens kReflectionBoost times
// as often as the Fresnel reflectance says
// (LensSystem::FlareOptions::reflectionBoost):
// uncoated, about 60% of them would otherwise refract straight through
// (where only the direct image of a lamp needs them, a pixel or two),
// multi-coated 98%.
constexpr double kReflectionBoost = 4.0;

// With ghosts picked (ghostChoice), a source that keeps its direct image
// gives it this share of its paths (a lamp's direct image is a spot of a
// few pixels, or its bokeh disc); the rest each make one ghost.
constexpr double kDirectShare = 1.0 / 8.0;

// The pass's choice of ghost, one per path, where the camera's flare allows
// two reflections and no barrel (the paths with two reflections are then all
// that reach the film but the direct image): each two-reflection ghost
// (ghostPaths) with probability in proportion to its paraxial strength R_i
// R_j times the part of its bundle the apertures pass (plus a tenth, as a
// ghost that misses them on the axis may pass off it), its paths made with
// FlareOptions::ghost. About half of them reach the film, against about one
// in ten of the boosted reflect-or-refract paths, and each ghost gets paths in
// proportion to its strength. Surfaces whose d-line indices are equal (a
// cemented pair of equal nd) reflect only through dispersion and are not
// picked: their R is of order 1e-6.
struct GhostChoice {
  std::vector<LensSystem::FlareOptions> options;  // one per ghost, FlareOptions::ghost set
  Distribution1D pick;
  LensSystem::FlareOptions direct;  // no reflection: the direct image
};
std::optional<GhostChoice> ghostChoice(const LensSystem& lens, const LensSystem::FlareOptions& options) {
  if (options.maxReflections != 2 || options.barrelReflectance > 0.0) return std::nullopt;
  GhostChoice c;
  std::vector<float> weights;
  for (const GhostPath& g : ghostPaths(lens.prescription(), lens.coating().value_or(Coating::None))) {
    LensSystem::FlareOptions o = options;
    o.ghost = std::pair{g.first, g.second};
    c.options.push_back(std::move(o));
    weights.push_back(float(g.strength * (0.1 + g.passing)));
  }
  c.pick = Distribution1D(weights);
  if (c.pick.empty()) return std::nullopt;
  c.direct = options;
  c.direct.maxReflections = 0;
  return c;
}

// A lamp's lit surfaces take 1/kLitSurfaceShare of a light's paths: most of
// them meet a surface the lens does not see or refract straight through the
// lens (only reflected paths count), and their ghosts are wide and soft.
constexpr std::uint64_t kLitSurfaceShare = 8;

struct Deposit {
  std::uint32_t pixel;
  Vec3d value;
};

}  // namespace

FlareImage flareLightPass(const LensCamera& camera, std::span<const PunctualLight> lights,
                          std::uint64_t paths, std::uint64_t seed, const FilmResponse* response, int threads,
                          bool withVariance, const FlareScene& scene) {
  const FilmGeometry& film = camera.film();
  const std::size_t pixelCount = std::size_t(film.width) * std::size_t(film.height);
  FlareImage image{film.width, film.height, std::vector<Rgb>(pixelCount, Rgb{}),
                   std::vector<Rgb>(withVariance ? pixelCount : 0, Rgb{})};
  if (paths == 0) return image;
  const LensSystem& lens = camera.lens();
  LensSystem::FlareOptions options = camera.flareOptions();
  options.reflectionBoost = kReflectionBoost;
  const std::optional<GhostChoice> ghosts = ghostChoice(lens, options);
  const LensFrame frame{camera, camera.worldFromCamera().inverse()};
  const double discRadius = 1.2 * lens.frontApertureRadius();
  const double discArea = kPi * discRadius * discRadius;  // mm^2
  const double pixelArea = (film.sensorWidthMm / film.width) * (film.sensorHeightMm / film.height);
  const bool dispersive = camera.tracesWavelengths();

  // The sources, in a fixed order (their index keys their random streams).
  std::vector<Source> sources;
  for (const PunctualLight& l : lights) {
    Source s;
    if (const std::optional<LensLight> light = lensLight(frame, l)) {
      s.light = *light;
      s.paths = paths;
    }
    sources.push_back(s);  // an unseen light keeps its index (its streams' key), with no path
  }
  Distribution1D trianglePick;
  if (scene.emitters && scene.emitters->emissiveTriangleCount() > 0) {
    trianglePick = Distribution1D(emitterWeights(frame, *scene.emitters, discRadius));
    if (!trianglePick.empty()) sources.push_back({Source::Kind::Emitters, {}, paths, true});
  }
  if (scene.environment && scene.environment->hasSun())
    sources.push_back({Source::Kind::Sun, {}, paths, true});
  if (scene.geometry && scene.litSurfaces)
    for (const PunctualLight& l : lights)
      if (isFlareLamp(l) && maxComponent(l.intensity) > 0)
        sources.push_back(
            {Source::Kind::LitSurface, {}, std::max<std::uint64_t>(1, paths / kLitSurfaceShare), true, &l});

  std::vector<Vec3d> sums(pixelCount, Vec3d{});
  // The deposits' squares, and one source's own sum (its variance needs it):
  // only when asked, as they triple the memory.
  std::vector<Vec3d> variances(withVariance ? pixelCount : 0), sourceSums(withVariance ? pixelCount : 0);
  // Chunks run kGroup at a time, so the deposits held at once stay bounded
  // (kGroup x kFlareChunk paths) however many paths a source takes.
  constexpr std::uint64_t kGroup = 64;
  std::vector<std::vector<Deposit>> deposits(static_cast<std::size_t>(kGroup));
  const int arenaThreads = threads > 0 ? threads : tbb::task_arena::automatic;
  tbb::task_arena arena(arenaThreads);
  // Is the segment from the disc point (world) toward the source open?
  const auto visible = [&](const Shadow& shadow) {
    if (!scene.geometry) return true;
    Ray ray{shadow.from, shadow.direction, 0.0f, kInfinityF, 0.0f};
    if (std::isfinite(shadow.distance))
      ray.tMax = shadow.distance * (1 - 1e-4f);  // short of the source's own surface
    return !scene.geometry->occluded(ray);
  };
  for (std::size_t si = 0; si < sources.size(); ++si) {
    const Source& source = sources[si];
    if (source.paths == 0) continue;
    std::fill(sourceSums.begin(), sourceSums.end(), Vec3d{});
    // Each path's share of the flux through the disc, in film units per
    // pixel: the exposure scale times irradiance (flux over pixel area).
    const double share = camera.exposureScale() * discArea / double(source.paths) / pixelArea;
    const std::uint64_t chunks = (source.paths + kFlareChunk - 1) / kFlareChunk;
    const auto runChunk = [&](std::uint64_t c) {
      ChunkStream random(seed, si, c);
      std::vector<Deposit>& out = deposits[std::size_t(c % kGroup)];
      out.clear();
      const std::uint64_t end = std::min(source.paths, (c + 1) * kFlareChunk);
      for (std::uint64_t k = c * kFlareChunk; k < end; ++k) {
        const double rho = discRadius * std::sqrt(random()), phi = 2.0 * kPi * random();
        const Vec3d target{rho * std::cos(phi), rho * std::sin(phi), 0.0};
        LensRay ray;
        double irradiance = 0.0;  // across the disc's plane at the target, per unit of `emitted`
        Rgb emitted;              // intensity (point), irradiance (directional) or radiance
        // From the disc point (world) toward the source: tested only for a
        // path that deposits (most do not), as it takes no random number.
        Shadow shadow;
        std::optional<SurfaceHit> lit;  // a lit-surface path's point on the scene
        Vec3f litWo, litWi;             // from there toward the disc point and toward the lamp
        switch (source.kind) {
          case Source::Kind::Punctual: {
            const LensLight& light = source.light;
            emitted = light.intensity;
            if (light.atInfinity) {
              // Started in front of the lens: a front surface bulges at most its radius.
              ray = {target - light.direction * ((discRadius + 10.0) / light.direction.z), light.direction};
              irradiance = light.direction.z;
            } else {
              const Vec3d d = target - light.point;
              const double r2 = lengthSquared(d);
              ray = {light.point, d};
              irradiance = (d.z / std::sqrt(r2)) / (r2 * 1e-6);  // cos / r^2, r in metres
            }
            if (light.atInfinity) {
              shadow = {frame.worldOf(target), light.world, kInfinityF};
            } else {
              const Vec3f from = frame.worldOf(target), d = light.world - from;
              const float distance = length(d);
              if (!(distance > 0.0f)) continue;
              shadow = {from, d / distance, distance};
            }
            break;
          }
          case Source::Kind::Emitters: {
            // A triangle by its flux into the disc, a point uniform on it
            // (density per solid angle at the disc point).
            const Vec3f from = frame.worldOf(target);
            float uPick = 0.0f;
            const std::size_t t = trianglePick.sample(float(random()), &uPick);
            const Vec2f u{uPick, float(random())};
            const std::optional<LightSample> ls = scene.emitters->sampleEmissiveTriangle(t, from, u);
            if (!ls || !(ls->pdf > 0.0f)) continue;
            const Vec3d point = frame.lensOf(from + ls->wi * ls->distance);
            if (!(point.z < 0.0)) continue;  // behind the front vertex
            const Vec3d d = target - point;
            ray = {point, d};
            irradiance = (d.z / length(d)) / (double(ls->pdf) * double(trianglePick.probability(t)));
            emitted = ls->radiance;
            shadow = {from, ls->wi, ls->distance};
            break;
          }
          case Source::Kind::Sun: {
            const Vec3f from = frame.worldOf(target);
            const std::optional<EnvironmentSample> es =
                scene.environment->sampleSun({float(random()), float(random())});
            if (!es) continue;
            const Vec3d travel = normalize(frame.cameraFromWorld.vector(-Vec3d(es->direction)));
            if (!(travel.z > 0.0)) continue;  // behind the lens
            ray = {target - travel * ((discRadius + 10.0) / travel.z), travel};
            irradiance = travel.z / double(es->pdf);
            emitted = es->radiance;
            shadow = {from, es->direction, kInfinityF};
            break;
          }
          case Source::Kind::LitSurface: {
            // From the lamp to the first surface x, then toward the disc point
            // as x's BSDF sends it: the flux through the disc's share is the
            // lamp's intensity over the direction's density times
            // litSurfaceReflection (with the disc point's cosine / r^2); the
            // distance to x cancels (x's irradiance against the area a
            // direction covers there).
            const PunctualLight& lamp = *source.lamp;
            const LampDirection dir = sampleLampDirection(lamp, random(), random());
            lit = scene.geometry->intersect(Ray{lamp.position, dir.direction, 0.0f, kInfinityF, 0.0f});
            if (!lit) continue;
            float scale = rangeWindow(lamp, lit->t);
            if (lamp.type == PunctualLight::Type::Spot) scale *= spotAttenuation(lamp, dir.direction);
            if (!(scale > 0.0f)) continue;
            const Vec3d point = frame.lensOf(lit->position);
            if (!(point.z < 0.0)) continue;  // behind the front vertex
            const Vec3d d = target - point;
            const double r2 = lengthSquared(d);
            ray = {point, d};
            irradiance = (d.z / std::sqrt(r2)) / (r2 * 1e-6) / dir.pdf;
            emitted = lamp.intensity * scale;
            const Vec3f from = frame.worldOf(target), toSurface = lit->position - from;
            const float distance = length(toSurface);
            if (!(distance > 0.0f)) continue;
            litWo = -toSurface / distance;
            litWi = -dir.direction;
            shadow = {from, toSurface / distance, distance};
            break;
          }
        }
        double wavelength = kWavelengthDNm;
        // The source's colour on the film as the renderer takes a camera
        // sample's: spectral transport through the film's response (the
        // lens at the hero wavelength when it disperses), or RGB with one
        // wavelength weighted into the channels when the lens disperses.
        Rgb colour = emitted;
        const float uWavelength = float(random());
        if (response) {
          SampledWavelengths lambdas = SampledWavelengths::sample(uWavelength, *response);
          if (dispersive) {
            wavelength = lambdas.hero();
            lambdas.terminateSecondary();
          }
          Spectrum light = lambdas.illuminant(emitted);
          if (lit) light *= litSurfaceReflection(*scene.litSurfaces, *lit, litWo, litWi, lambdas);
          colour = lambdas.toFilm(light);
        } else {
          if (dispersive) {
            const WavelengthSample ws = sampleWavelength(uWavelength);
            wavelength = ws.wavelengthNm;
            colour = colour * ws.weight;
          }
          if (lit) {
            SampledWavelengths rgb = SampledWavelengths::rgb();
            colour = rgb.toFilm(rgb.illuminant(colour) *
                                litSurfaceReflection(*scene.litSurfaces, *lit, litWo, litWi, rgb));
          }
        }
        if (lit && !(maxComponent(colour) > 0.0f)) continue;  // x sends nothing toward the disc point
        LensSystem::FlareTrace t;
        if (ghosts) {
          // The direct image, or one ghost; the weight over the choice's probability.
          double p = 1.0;
          if (!source.reflectedOnly && random() < kDirectShare) {
            t = lens.traceFromSceneWithFlare(ray, ghosts->direct, random, wavelength);
            p = kDirectShare;
          } else {
            const std::size_t g = ghosts->pick.sample(float(random()));
            t = lens.traceFromSceneWithFlare(ray, ghosts->options[g], random, wavelength);
            p = (source.reflectedOnly ? 1.0 : 1.0 - kDirectShare) * double(ghosts->pick.probability(g));
          }
          t.ray.transmittance /= p;
        } else {
          t = lens.traceFromSceneWithFlare(ray, options, random, wavelength);
        }
        if (t.end != LensSystem::FlareTrace::End::Film) continue;
        // The direct image of an emitter or the sun is the camera paths'.
        if (source.reflectedOnly && t.reflections == 0) continue;
        const Vec2d raster = camera.rasterOfFilmHit(t.ray);  // on the film, shifted or tilted as it is
        if (!(raster.x >= 0.0 && raster.y >= 0.0 && raster.x < film.width && raster.y < film.height))
          continue;
        if (!visible(shadow)) continue;
        const auto pixel = std::uint32_t(int(raster.y) * film.width + int(raster.x));
        const double w = share * irradiance * t.ray.transmittance;
        out.push_back({pixel, Vec3d(colour) * w});
      }
    };
    for (std::uint64_t group = 0; group < chunks; group += kGroup) {
      const std::uint64_t end = std::min(chunks, group + kGroup);
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::uint64_t>(group, end, 1), [&](const auto& r) {
          for (std::uint64_t c = r.begin(); c != r.end(); ++c) runChunk(c);
        });
      });
      // In chunk order, whatever ran where.
      for (std::uint64_t c = group; c < end; ++c)
        for (const Deposit& d : deposits[std::size_t(c % kGroup)]) {
          sums[d.pixel] += d.value;  // the image's bits, with or without the variance
          if (withVariance) {
            sourceSums[d.pixel] += d.value;
            variances[d.pixel] += d.value * d.value;
          }
        }
    }
    if (withVariance)
      for (std::size_t i = 0; i < pixelCount; ++i)
        variances[i] -= sourceSums[i] * sourceSums[i] / double(source.paths);
  }
  for (std::size_t i = 0; i < pixelCount; ++i) image.pixels[i] = Rgb(sums[i]);
  if (!withVariance) return image;
  // A ghost's pixel that few or no paths reached would report little or no
  // variance where its neighbours, as likely to be hit, report theirs: each
  // pixel takes at least its 3 x 3 neighbourhood's mean (never less than its
  // own, so the sharp direct image keeps its own).
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      Vec3d mean{};
      int n = 0;
      for (int v = std::max(0, y - 1); v <= std::min(film.height - 1, y + 1); ++v)
        for (int u = std::max(0, x - 1); u <= std::min(film.width - 1, x + 1); ++u, ++n)
          mean += variances[std::size_t(v) * std::size_t(film.width) + std::size_t(u)];
      mean = mean / double(n);
      const Vec3d& own = variances[std::size_t(y) * std::size_t(film.width) + std::size_t(x)];
      image.variance[std::size_t(y) * std::size_t(film.width) + std::size_t(x)] = Rgb(Vec3d{
          std::max({0.0, own.x, mean.x}), std::max({0.0, own.y, mean.y}), std::max({0.0, own.z, mean.z})});
    }
  return image;
}

}  // namespace lensrt
