#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <span>
#include <stdexcept>
#include <vector>

#include "render/flare_light_pass.h"
#include "render/sampler.h"

namespace lensrt {

namespace {
// Camera samples per generateRays call: enough for a camera to batch, few
// enough to stay in cache whatever the spp.
constexpr std::uint64_t kCameraBatch = 256;
// The longest per-pixel table of sampler seeds; deeper paths hash their own.
constexpr std::uint32_t kSeedTableDimensions = 256;

// Samples [first, last) of every pixel of the state's region.
void renderPass(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                FilmState& state, std::uint32_t firstSample, std::uint32_t lastSample, Progress* progress) {
  const FilmGeometry& film = camera.film();
  const PixelRegion region = state.region();
  const int tile = std::max(1, settings.tileSize);
  const int tilesX = (region.width() + tile - 1) / tile, tilesY = (region.height() + tile - 1) / tile;
  const std::uint32_t spp = lastSample - firstSample;
  std::atomic<std::uint64_t> blocked{0};
  // Spectral transport when the settings have a film response; a camera
  // that traces wavelengths (dispersion) follows each sample's hero.
  const FilmResponse* response = settings.filmResponse.get();
  // The camera node's origin and viewing axis at rest: depth is measured
  // from them (a lens's rays leave from its front glass, not from there).
  Ray node{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
  node = camera.worldFromCamera()(node);
  node.direction = normalize(node.direction);
  // A diffracting camera bends each ray by its wavelength, as a dispersive one traces it.
  const bool dispersive = camera.tracesWavelengths() || camera.diffracts();
  // Spectral transport through a camera that weighs the other wavelengths:
  // the path carries all four past the lens (camera/wavelength_lanes.h).
  const bool lanes = response && dispersive && camera.carriesLanes();
  const std::optional<AdaptiveSampling>& adaptive = settings.adaptive;
  const std::optional<SceneIds> ids =
      state.aovs().ids() ? std::optional<SceneIds>(integrator.scene().desc()) : std::nullopt;
  const MotionFlow* flow = state.aovs().flow ? settings.flow.get() : nullptr;
  if (state.aovs().flow && !flow) throw std::invalid_argument("the flow AOV needs the moments it compares");

  const auto renderTile = [&](int t) {
    const int x0 = region.x0 + (t % tilesX) * tile, y0 = region.y0 + (t / tilesX) * tile;
    const int x1 = std::min(x0 + tile, region.x1), y1 = std::min(y0 + tile, region.y1);
    std::uint64_t tileBlocked = 0, tileSamples = 0, tileSkipped = 0;
    // Camera rays are made kCameraBatch samples per call (the samples of a
    // tile row, pixel by pixel, in order), so a camera can trace them together
    // (the full lens does); each still depends only on (seed, pixel, sample index).
    const std::size_t batch =
        std::size_t(std::min<std::uint64_t>(kCameraBatch, std::uint64_t(x1 - x0) * spp));
    std::vector<CameraSample> samples(batch);
    std::vector<std::optional<CameraRay>> rays(batch);
    std::vector<SampledWavelengths> lambdas(batch, SampledWavelengths::rgb());
    std::vector<Rgb> dispersionWeights(dispersive && !response ? batch : 0);
    std::vector<Sampler> samplers;
    samplers.reserve(batch);
    // The seeds of the pixels a batch covers, shared by their samples (the
    // table is as long as a path's dimensions, up to a cap for deep paths).
    const std::uint32_t dimensions = std::min(integrator.sampleDimensions(), kSeedTableDimensions);
    std::vector<PixelSeeds> pixelSeeds(batch / spp + 2);
    // The row's pixels that take this pass's samples: all of them, or with
    // adaptive sampling those that have not converged.
    std::vector<int> columns;
    columns.reserve(std::size_t(x1 - x0));
    for (int y = y0; y < y1; ++y) {
      columns.clear();
      for (int x = x0; x < x1; ++x) {
        if (!adaptive || keepsSampling(*adaptive, state.pixel(x, y), int(firstSample)))
          columns.push_back(x);
        else if (state.pixel(x, y).samplesTaken() == firstSample)  // stops here: the bar counts what it skips
          tileSkipped += std::uint64_t(std::max(0, settings.samplesPerPixel - int(firstSample)));
      }
      const std::uint64_t rowSamples = std::uint64_t(columns.size()) * spp;
      tileSamples += rowSamples;
      for (std::uint64_t first = 0; first < rowSamples; first += batch) {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(batch, rowSamples - first));
        const auto pixelOf = [&](std::uint64_t j) {
          return std::uint64_t(y) * std::uint64_t(film.width) + std::uint64_t(columns[j / spp]);
        };
        const auto sampleOf = [&](std::uint64_t j) { return firstSample + std::uint32_t(j % spp); };
        samplers.clear();
        const std::uint64_t firstPixel = first / spp;
        for (std::uint64_t p = firstPixel; p <= (first + n - 1) / spp; ++p)
          pixelSeeds[p - firstPixel].reset(settings.seed, pixelOf(p * spp), dimensions);
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint64_t j = first + k;
          const Sampler& sampler = samplers.emplace_back(pixelSeeds[j / spp - firstPixel], sampleOf(j));
          static_assert(kDimFilm == 0);
          const SampleBlock u = sampler.block(kDimFilm);
          const Vec2f offset = u.get2D(kDimFilm);
          CameraSample& cs = samples[k];
          cs.film = {float(columns[j / spp]) + offset.x, float(y) + offset.y};
          cs.lens = u.get2D(kDimLens);
          if (camera.diffracts()) cs.diffraction = sampler.get2D(kDimDiffraction);
          // The sampler's 1D stream is a scrambled van der Corput sequence in
          // the sample index: a pixel's wavelengths are stratified (any
          // power-of-two prefix, so passes and resumes keep it). Cameras
          // that ignore the wavelength keep the default.
          if (response) {
            lambdas[k] = SampledWavelengths::sample(u.get1D(kDimWavelength), *response);
            if (dispersive) {
              cs.wavelengthNm = lambdas[k].hero();
              if (lanes)
                cs.secondaryNm = {lambdas[k].nm(1), lambdas[k].nm(2), lambdas[k].nm(3)};
              else
                lambdas[k].terminateSecondary();
            }
          } else if (dispersive) {
            // RGB transport: one wavelength per sample, weighted into RGB.
            const WavelengthSample ws = sampleWavelength(u.get1D(kDimWavelength));
            cs.wavelengthNm = ws.wavelengthNm;
            dispersionWeights[k] = ws.weight;
          }
        }
        camera.generateRays(std::span(samples).first(n), std::span(rays).first(n));
        if (lanes)
          for (std::size_t k = 0; k < n; ++k) {
            if (rays[k] && rays[k]->laneWeights)
              lambdas[k].weightLanes(*rays[k]->laneWeights);
            else
              lambdas[k].terminateSecondary();
          }
        if (settings.timing) {
          // The time shares the wavelength's Sobol pair (its second
          // coordinate, unused otherwise), so the two are stratified together.
          for (std::size_t k = 0; k < n; ++k)
            if (rays[k]) {
              rays[k]->ray.time = settings.timing->sampleTime(samples[k].film, film.width, film.height,
                                                              samplers[k].get2D(kDimWavelength).y);
              rays[k]->ray = settings.timing->moveWithCamera(rays[k]->ray);
            }
        }
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint64_t j = first + k;
          PixelAccumulator& acc = state.pixel(columns[j / spp], y);
          const std::optional<CameraRay>& cr = rays[k];
          if (!cr) {
            acc.addBlocked();
            ++tileBlocked;
          } else {
            PathSample path = integrator.trace(cr->ray, samplers[k], lambdas[k], cr->lensReflected);
            if (path.hit) {
              Ray at = node;  // where the node is at the ray's time
              if (settings.timing) {
                at.time = cr->ray.time;
                at = settings.timing->moveWithCamera(at);
              }
              const Vec3f toHit = path.position - at.origin;
              path.distance = length(toHit);
              path.planarZ = dot(toHit, normalize(at.direction));
            }
            if (!dispersionWeights.empty()) path.radiance = path.radiance * dispersionWeights[k];
            if (acc.add(path, cr->weight, cr->lensReflected) && state.aovs().coords())
              state.coords(columns[j / spp], y).add(path);
            if (ids && !cr->lensReflected) {
              const std::size_t m = std::size_t(path.material + 1);
              const std::uint32_t materialBits =
                  path.hit && m < ids->materialBits.size() ? ids->materialBits[m] : 0;
              if (path.hit && path.instance >= 0 && std::size_t(path.instance) < ids->instanceBits.size())
                state.ids(columns[j / spp], y)
                    .add(ids->instanceBits[std::size_t(path.instance)],
                         ids->instanceNode[std::size_t(path.instance)], materialBits, path.material);
              else
                state.ids(columns[j / spp], y).add(0, -1, 0, -1);
            }
            // Flow: of the pixel's first samples that hit (kFlowSamplesPerPixel);
            // a blocked or lens-reflected sample (flare) has no first hit of its own.
            if (flow && path.hit && !cr->lensReflected) {
              FlowSums& sums = state.flow(columns[j / spp], y);
              if (!sums.full())
                sums.add(sampleFlow(*flow, integrator.scene().desc(), camera, path.instance, path.primitive,
                                    path.barycentric, sums.hints),
                         path.instance);
            }
          }
        }
      }
    }
    blocked.fetch_add(tileBlocked, std::memory_order_relaxed);
    if (progress) {
      progress->add(tileSamples);
      progress->skip(tileSkipped);
    }
  };

  const int threads = settings.threads > 0 ? settings.threads : tbb::task_arena::automatic;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<int>& r) {
      for (int t = r.begin(); t != r.end(); ++t) renderTile(t);
    });
  });
  state.blockedCameraRays += blocked.load();
  state.setSamplesDone(int(lastSample));
}

// Samples [first, last), cut at the decision points of adaptive sampling,
// where each pixel decides whether it goes on: whatever [first, last) a
// caller asks for, every decision is taken at the same sample count.
void renderSpan(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                FilmState& state, int first, int last, Progress* progress) {
  while (first < last) {
    const int end = settings.adaptive ? std::min(last, nextDecisionPoint(*settings.adaptive, first)) : last;
    renderPass(camera, integrator, settings, state, std::uint32_t(first), std::uint32_t(end), progress);
    first = end;
  }
}

}  // namespace

bool renderPasses(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                  FilmState& state, const PassControl* control, Progress* progress) {
  const FilmGeometry& film = camera.film();
  if (!PixelRegion::wholeFrame(film.width, film.height).contains(state.region()))
    throw std::invalid_argument("the region " + state.region().describe() + " is not inside the " +
                                std::to_string(film.width) + "x" + std::to_string(film.height) + " frame");
  const int target = settings.samplesPerPixel;
  if (!control) {
    renderSpan(camera, integrator, settings, state, state.samplesDone(), target, progress);
    return true;
  }
  // A stop is honoured after a pass, so the pass in flight (the first one
  // included) always finishes and the image has whole passes.
  int passSpp = 1;
  while (state.samplesDone() < target) {
    const int first = state.samplesDone(), last = std::min(target, first + passSpp);
    const auto start = std::chrono::steady_clock::now();
    renderSpan(camera, integrator, settings, state, first, last, progress);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds * 2 < control->passSeconds && passSpp < (1 << 20)) passSpp *= 2;
    if (state.samplesDone() >= target) break;
    if (control->stopRequested && control->stopRequested()) return false;
    if (control->afterPass) control->afterPass(state);
  }
  return true;
}

RenderOutput renderOutput(const Camera& camera, const FilmState& state, const FlareImage* flareLight) {
  RenderOutput out;
  out.image = state.image(camera.film().width, camera.film().height);
  if (flareLight) {
    const PixelRegion region = state.region();
    const std::array<int, 3> rgb{out.image.channelIndex("R"), out.image.channelIndex("G"),
                                 out.image.channelIndex("B")};
    for (int y = region.y0; y < region.y1; ++y)
      for (int x = region.x0; x < region.x1; ++x)
        for (int c = 0; c < 3; ++c)
          out.image.at(x - region.x0, y - region.y0, rgb[std::size_t(c)]) += flareLight->at(x, y)[c];
    // The light pass's noise joins the camera paths' (independent: variances add).
    const std::array<int, 3> var{out.image.channelIndex("variance.R"), out.image.channelIndex("variance.G"),
                                 out.image.channelIndex("variance.B")};
    if (var[0] >= 0 && !flareLight->variance.empty())
      for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
          const Rgb& v =
              flareLight->variance[std::size_t(y) * std::size_t(flareLight->width) + std::size_t(x)];
          for (int c = 0; c < 3; ++c) out.image.at(x - region.x0, y - region.y0, var[std::size_t(c)]) += v[c];
        }
  }
  out.droppedSamples = state.droppedSamples();
  out.cameraSamples = state.samplesTaken();
  out.samplesDone = state.samplesDone();
  out.blockedCameraRays = state.blockedCameraRays;
  return out;
}

RenderOutput renderImage(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                         Progress* progress) {
  const FilmGeometry& film = camera.film();
  if (film.width <= 0 || film.height <= 0) throw std::invalid_argument("film size must be positive");
  if (settings.samplesPerPixel < 1) throw std::invalid_argument("samples per pixel must be at least 1");
  if (settings.adaptive && !(settings.adaptive->noiseThreshold > 0 && settings.adaptive->minSamples >= 1))
    throw std::invalid_argument("adaptive sampling needs a positive noise threshold and at least 1 sample");
  FilmState state(settings.region.value_or(PixelRegion::wholeFrame(film.width, film.height)), settings.aovs);
  renderPasses(camera, integrator, settings, state, nullptr, progress);
  return renderOutput(camera, state, settings.flareLight.get());
}

}  // namespace lensrt
