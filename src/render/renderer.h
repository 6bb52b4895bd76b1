// Renders a whole image: the film is cut into square tiles that TBB runs in
// parallel (in an arena of `threads` workers); each pixel's samples are traced
// and summed in sample order by one task, so the image is bit-identical for
// any thread count and any tile size.
#pragma once

#include <cstdint>

#include "camera/camera.h"
#include "image/image.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/progress.h"

namespace lensrt {

struct RenderSettings {
  int samplesPerPixel = 16;
  std::uint64_t seed = 0;
  int threads = 0;  // 0: all cores
  int tileSize = 16;
  AovSelection aovs;
};

struct RenderOutput {
  Image image;                       // channels per filmChannels(aovs), size of camera.film()
  std::uint64_t droppedSamples = 0;  // NaN / infinite radiance
  std::uint64_t cameraSamples = 0;      // width x height x spp
  std::uint64_t blockedCameraRays = 0;  // samples the optics blocked (vignetting)
  // Fraction of camera samples that left the lens into the scene.
  double cameraRayEfficiency() const {
    return cameraSamples ? 1.0 - double(blockedCameraRays) / double(cameraSamples) : 1.0;
  }
};

// Wavelengths handed to the camera are uniform in this range (nm).
inline constexpr float kWavelengthMinNm = 380.0f;
inline constexpr float kWavelengthMaxNm = 780.0f;

RenderOutput renderImage(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                         Progress* progress = nullptr);

}  // namespace lensrt
