#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <span>
#include <stdexcept>
#include <vector>

#include "render/sampler.h"

namespace lensrt {

namespace {
// Camera samples per generateRays call: enough for a camera to batch, few
// enough to stay in cache whatever the spp.
constexpr std::uint64_t kCameraBatch = 256;
}  // namespace

RenderOutput renderImage(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                         Progress* progress) {
  const FilmGeometry& film = camera.film();
  if (film.width <= 0 || film.height <= 0) throw std::invalid_argument("film size must be positive");
  if (settings.samplesPerPixel < 1) throw std::invalid_argument("samples per pixel must be at least 1");
  const int tile = std::max(1, settings.tileSize);
  const int tilesX = (film.width + tile - 1) / tile, tilesY = (film.height + tile - 1) / tile;

  RenderOutput out;
  out.image = Image(film.width, film.height, filmChannels(settings.aovs));
  std::atomic<std::uint64_t> dropped{0};
  std::atomic<std::uint64_t> blocked{0};
  const std::uint32_t spp = std::uint32_t(settings.samplesPerPixel);

  const auto renderTile = [&](int t) {
    const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
    const int x1 = std::min(x0 + tile, film.width), y1 = std::min(y0 + tile, film.height);
    std::uint64_t tileDropped = 0, tileBlocked = 0;
    // Camera rays are made kCameraBatch samples per call (the samples of a
    // tile row, pixel by pixel, in order), so a camera can trace them together
    // (the full lens does); each still depends only on (seed, pixel, sample index).
    const std::uint64_t rowSamples = std::uint64_t(x1 - x0) * spp;
    const std::size_t batch = std::size_t(std::min<std::uint64_t>(kCameraBatch, rowSamples));
    std::vector<CameraSample> samples(batch);
    std::vector<std::optional<CameraRay>> rays(batch);
    for (int y = y0; y < y1; ++y) {
      PixelAccumulator acc;
      for (std::uint64_t first = 0; first < rowSamples; first += batch) {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(batch, rowSamples - first));
        const auto pixelOf = [&](std::uint64_t j) {
          return std::uint64_t(y) * std::uint64_t(film.width) + std::uint64_t(x0) + j / spp;
        };
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint64_t j = first + k;
          const Sampler sampler(settings.seed, pixelOf(j), std::uint32_t(j % spp));
          const Vec2f offset = sampler.get2D(kDimFilm);
          CameraSample& cs = samples[k];
          cs.film = {float(x0 + int(j / spp)) + offset.x, float(y) + offset.y};
          cs.lens = sampler.get2D(kDimLens);
          cs.wavelengthNm =
              kWavelengthMinNm + (kWavelengthMaxNm - kWavelengthMinNm) * sampler.get1D(kDimWavelength);
        }
        camera.generateRays(std::span(samples).first(n), std::span(rays).first(n));
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint64_t j = first + k;
          const std::optional<CameraRay>& cr = rays[k];
          if (!cr) {
            acc.addBlocked();
            ++tileBlocked;
          } else {
            acc.add(integrator.trace(cr->ray, Sampler(settings.seed, pixelOf(j), std::uint32_t(j % spp))),
                    cr->weight);
          }
          if ((j + 1) % spp == 0) {  // the pixel's last sample
            acc.write(settings.aovs, &out.image.at(x0 + int(j / spp), y, 0));
            tileDropped += acc.droppedSamples();
            acc = PixelAccumulator();
          }
        }
      }
    }
    dropped.fetch_add(tileDropped, std::memory_order_relaxed);
    blocked.fetch_add(tileBlocked, std::memory_order_relaxed);
    if (progress) progress->add(std::uint64_t(x1 - x0) * std::uint64_t(y1 - y0) * spp);
  };

  const int threads = settings.threads > 0 ? settings.threads : tbb::task_arena::automatic;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<int>& r) {
      for (int t = r.begin(); t != r.end(); ++t) renderTile(t);
    });
  });
  out.droppedSamples = dropped.load();
  out.cameraSamples = std::uint64_t(film.width) * std::uint64_t(film.height) * spp;
  out.blockedCameraRays = blocked.load();
  return out;
}

}  // namespace lensrt
