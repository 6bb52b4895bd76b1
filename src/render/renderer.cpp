#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "render/sampler.h"

namespace lensrt {

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
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::uint64_t pixelIndex = std::uint64_t(y) * std::uint64_t(film.width) + std::uint64_t(x);
        PixelAccumulator acc;
        for (std::uint32_t i = 0; i < spp; ++i) {
          const Sampler sampler(settings.seed, pixelIndex, i);
          const Vec2f offset = sampler.get2D(kDimFilm);
          CameraSample cs;
          cs.film = {float(x) + offset.x, float(y) + offset.y};
          cs.lens = sampler.get2D(kDimLens);
          cs.wavelengthNm =
              kWavelengthMinNm + (kWavelengthMaxNm - kWavelengthMinNm) * sampler.get1D(kDimWavelength);
          const std::optional<CameraRay> cr = camera.generateRay(cs);
          if (!cr) {
            acc.addBlocked();
            ++tileBlocked;
            continue;
          }
          acc.add(integrator.trace(cr->ray, sampler), cr->weight);
        }
        acc.write(settings.aovs, &out.image.at(x, y, 0));
        tileDropped += acc.droppedSamples();
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
