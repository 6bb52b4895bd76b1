// Renders an image, or a region of it: the region is cut into square tiles
// that TBB runs in parallel (in an arena of `threads` workers); each pixel's
// samples are traced and summed in sample order by one task, so the image is
// bit-identical for any thread count and any tile size. A render may run in
// passes of samples (all pixels get samples [a, b), then [b, c), ...): the
// sums live in a FilmState between passes, so the passes, a checkpoint and a
// resume change no bit either.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "camera/camera.h"
#include "image/image.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"
#include "render/film_response.h"
#include "render/film_state.h"
#include "render/integrator.h"
#include "render/motion_flow.h"
#include "render/pixel_region.h"
#include "render/progress.h"
#include "render/shutter_timing.h"
#include "render/spectral_response.h"

namespace lensrt {

struct FlareImage;  // render/flare_light_pass.h

struct RenderSettings {
  int samplesPerPixel = 16;  // the total to reach (a resumed render has done some); adaptive: the most
  // Stops converged pixels early (adaptive_sampling.h); none: every pixel
  // takes samplesPerPixel, with the bits of a render before it existed.
  std::optional<AdaptiveSampling> adaptive;
  std::uint64_t seed = 0;
  int threads = 0;  // 0: all cores
  int tileSize = 16;
  AovSelection aovs;
  std::optional<PixelRegion> region;  // none: the whole frame
  // Spectral transport through this response; none: RGB transport.
  std::shared_ptr<const FilmResponse> filmResponse;
  // When the samples are taken, for a scene that moves (motion blur, rolling
  // shutter); none: every ray at time 0, with the bits of a render before
  // motion existed.
  std::optional<ShutterTiming> timing;
  // --flare on: the light pass's image (punctual lights; still emitters'
  // and the environment sun's lens reflections, which the camera paths of a
  // flare camera skip), the whole frame, added to the output's R, G and B
  // (renderOutput); none: nothing.
  std::shared_ptr<const FlareImage> flareLight;
  // --aov flow: the moments the flow compares (required with aovs.flow).
  std::shared_ptr<const MotionFlow> flow;
};

struct RenderOutput {
  Image image;  // channels per filmChannels(aovs), the region's size placed in camera.film()
  std::uint64_t droppedSamples = 0;     // NaN / infinite radiance
  std::uint64_t cameraSamples = 0;      // width x height x spp (adaptive: the pixels' samples summed)
  int samplesDone = 0;                  // the passes' samples per pixel (adaptive: the most a pixel took)
  std::uint64_t blockedCameraRays = 0;  // samples the optics blocked (vignetting)
  // Fraction of camera samples that left the lens into the scene.
  double cameraRayEfficiency() const {
    return cameraSamples ? 1.0 - double(blockedCameraRays) / double(cameraSamples) : 1.0;
  }
};

// Wavelengths: each camera sample carries one, drawn from the film's mean
// response (spectral_response.h) through the sampler's stratified 1D stream,
// so a pixel's samples cover the spectrum evenly. With a camera that traces
// them (Camera::tracesWavelengths) each sample's radiance is weighted by its
// wavelength's RGB weight: a grey scene keeps its colour, with little extra noise.
RenderOutput renderImage(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                         Progress* progress = nullptr);

// How a render in passes is steered from outside (the command line).
struct PassControl {
  // Polled after each pass: true stops there.
  std::function<bool()> stopRequested;
  // Called after each pass but the last one (e.g. to write a checkpoint).
  std::function<void(const FilmState&)> afterPass;
  // Passes start at 1 spp and double while a pass takes less than this, so
  // a stop request is honoured within about this many seconds.
  double passSeconds = 1.0;
};

// Adds samples [state.samplesDone(), settings.samplesPerPixel) to every
// pixel of state.region() (adaptive: to every pixel that keeps sampling, with
// passes cut at the decision points), in passes. Returns false when stopped early (the
// state then holds whole passes: every pixel has state.samplesDone() samples).
// Without a control, one pass.
bool renderPasses(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                  FilmState& state, const PassControl* control = nullptr, Progress* progress = nullptr);

// The output of a finished (or stopped) state, plus the region's pixels of
// the flare light pass when there is one (the camera paths' sums stay
// apart from it, in the state, so checkpoints and resumes keep their bits).
RenderOutput renderOutput(const Camera& camera, const FilmState& state,
                          const FlareImage* flareLight = nullptr);

}  // namespace lensrt
