#include "render/flare_light_pass.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "camera/film_mapping.h"
#include "core/constants.h"
#include "render/lights.h"
#include "render/spectral_response.h"
#include "render/wavelengths.h"

namespace lensrt {

namespace {

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A chunk's stream: SplitMix64 from a key of (seed, light, chunk).
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
};

std::optional<LensLight> lensLight(const LensCamera& camera, const Transform& cameraFromWorld,
                                   const PunctualLight& l) {
  // Lens space: camera space in mm, from the front vertex (camera space's
  // origin is the entrance pupil; lens space's z runs toward the film).
  const auto toLens = [&](const Vec3d& cameraPoint) {
    return Vec3d{cameraPoint.x * 1e3, cameraPoint.y * 1e3, cameraPoint.z * 1e3 + camera.entrancePupilZ()};
  };
  LensLight out;
  if (l.type == PunctualLight::Type::Directional) {
    out.atInfinity = true;
    out.direction = normalize(cameraFromWorld.vector(Vec3d(l.direction)));
    if (!(out.direction.z > 0.0)) return std::nullopt;  // the light travels away from the lens
    out.intensity = l.intensity;
    return out;
  }
  out.point = toLens(cameraFromWorld.point(Vec3d(l.position)));
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

struct Deposit {
  std::uint32_t pixel;
  Vec3d value;
};

}  // namespace

FlareImage flareLightPass(const LensCamera& camera, std::span<const PunctualLight> lights,
                          std::uint64_t paths, std::uint64_t seed, const FilmResponse* response, int threads,
                          bool withVariance) {
  const FilmGeometry& film = camera.film();
  const std::size_t pixelCount = std::size_t(film.width) * std::size_t(film.height);
  FlareImage image{film.width, film.height, std::vector<Rgb>(pixelCount, Rgb{}),
                   std::vector<Rgb>(withVariance ? pixelCount : 0, Rgb{})};
  if (paths == 0 || lights.empty()) return image;
  const LensSystem& lens = camera.lens();
  const LensSystem::FlareOptions& options = camera.flareOptions();
  const Transform cameraFromWorld = camera.worldFromCamera().inverse();
  const double discRadius = 1.2 * lens.frontApertureRadius();
  const double discArea = kPi * discRadius * discRadius;  // mm^2
  const double pixelArea = (film.sensorWidthMm / film.width) * (film.sensorHeightMm / film.height);
  const bool dispersive = camera.tracesWavelengths();
  const std::uint64_t chunks = (paths + kFlareChunk - 1) / kFlareChunk;
  std::vector<Vec3d> sums(pixelCount, Vec3d{});
  // The deposits' squares, and one light's own sum (its variance needs it):
  // only when asked, as they triple the memory.
  std::vector<Vec3d> variances(withVariance ? pixelCount : 0), lightSums(withVariance ? pixelCount : 0);
  // Chunks run kGroup at a time, so the deposits held at once stay bounded
  // (kGroup x kFlareChunk paths) however many paths a light takes.
  constexpr std::uint64_t kGroup = 64;
  std::vector<std::vector<Deposit>> deposits(static_cast<std::size_t>(std::min(chunks, kGroup)));
  const int arenaThreads = threads > 0 ? threads : tbb::task_arena::automatic;
  tbb::task_arena arena(arenaThreads);
  for (std::size_t li = 0; li < lights.size(); ++li) {
    const std::optional<LensLight> light = lensLight(camera, cameraFromWorld, lights[li]);
    if (!light) continue;
    std::fill(lightSums.begin(), lightSums.end(), Vec3d{});
    // Each path's share of the flux through the disc, in film units per
    // pixel: the exposure scale times irradiance (flux over pixel area).
    const double share = camera.exposureScale() * discArea / double(paths) / pixelArea;
    const auto runChunk = [&](std::uint64_t c) {
      ChunkStream random(seed, li, c);
      std::vector<Deposit>& out = deposits[std::size_t(c % kGroup)];
      out.clear();
      const std::uint64_t end = std::min(paths, (c + 1) * kFlareChunk);
      for (std::uint64_t k = c * kFlareChunk; k < end; ++k) {
        const double rho = discRadius * std::sqrt(random()), phi = 2.0 * kPi * random();
        const Vec3d target{rho * std::cos(phi), rho * std::sin(phi), 0.0};
        LensRay ray;
        double irradiance = 0.0;  // across the disc's plane at the target, per unit intensity
        if (light->atInfinity) {
          // Started in front of the lens: a front surface bulges at most its radius.
          ray = {target - light->direction * ((discRadius + 10.0) / light->direction.z), light->direction};
          irradiance = light->direction.z;
        } else {
          const Vec3d d = target - light->point;
          const double r2 = lengthSquared(d);
          ray = {light->point, d};
          irradiance = (d.z / std::sqrt(r2)) / (r2 * 1e-6);  // cos / r^2, r in metres
        }
        double wavelength = kWavelengthDNm;
        // The light's colour on the film as the renderer takes a camera
        // sample's: spectral transport through the film's response (the
        // lens at the hero wavelength when it disperses), or RGB with one
        // wavelength weighted into the channels when the lens disperses.
        Rgb colour = light->intensity;
        const float uWavelength = float(random());
        if (response) {
          SampledWavelengths lambdas = SampledWavelengths::sample(uWavelength, *response);
          if (dispersive) {
            wavelength = lambdas.hero();
            lambdas.terminateSecondary();
          }
          colour = lambdas.toFilm(lambdas.illuminant(light->intensity));
        } else if (dispersive) {
          const WavelengthSample ws = sampleWavelength(uWavelength);
          wavelength = ws.wavelengthNm;
          colour = colour * ws.weight;
        }
        const LensSystem::FlareTrace t = lens.traceFromSceneWithFlare(ray, options, random, wavelength);
        if (t.end != LensSystem::FlareTrace::End::Film) continue;
        const double s = (camera.filmZ() - t.ray.origin.z) / t.ray.direction.z;
        const Vec2d upright{-(t.ray.origin.x + s * t.ray.direction.x),
                            -(t.ray.origin.y + s * t.ray.direction.y)};
        const Vec2d raster = rasterOfUprightSensorPointMm(film, upright);
        if (!(raster.x >= 0.0 && raster.y >= 0.0 && raster.x < film.width && raster.y < film.height))
          continue;
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
            lightSums[d.pixel] += d.value;
            variances[d.pixel] += d.value * d.value;
          }
        }
    }
    if (withVariance)
      for (std::size_t i = 0; i < pixelCount; ++i)
        variances[i] -= lightSums[i] * lightSums[i] / double(paths);
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
