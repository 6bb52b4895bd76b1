// The light pass of lens flare (--flare on): small bright sources, which camera
// paths never find (punctual lights) or find only as rare heavy samples after a
// lens reflection, sent through the full lens from their side (particle tracing,
// LensSystem::traceFromSceneWithFlare) and deposited on the film; deterministic
// (chunks with their own streams, summed in order). The sources, the sampling, the
// variance and the determinism: docs/design/flare-light-pass.md.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "camera/lens_camera.h"
#include "core/vec.h"
#include "scene/scene_desc.h"

namespace lensrt {

class Environment;
class FilmResponse;
class LightSet;
class MaterialTable;
class RenderScene;

inline constexpr std::uint64_t kFlareChunk = 4096;

struct FlareImage {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;    // row by row, the whole frame
  std::vector<Rgb> variance;  // of each pixel's estimate, the same layout
  const Rgb& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// What the pass takes besides the punctual lights, and what may hide them.
struct FlareScene {
  const RenderScene* geometry = nullptr;     // the shadow rays; none: nothing hides a source
  const LightSet* emitters = nullptr;        // its still emissive triangles; none: no emitter
  const Environment* environment = nullptr;  // its sun; none: no sun
  // With geometry: the lamps' (isFlareLamp) light on the surfaces the lens
  // sees, as camera paths with at least one scattering event take it
  // (IntegratorSettings::maxDepth >= 1); none: no lit surface.
  const MaterialTable* litSurfaces = nullptr;
};

// `lights` in world space; a light behind the front vertex or pointing away
// (a spot's cone) adds nothing. `paths` for each punctual light, for the
// still emitters together (as many as for one light: each of their paths
// costs a whole lens trace, and few reflect), for the sun and for each
// lamp's lit surfaces. The
// camera must have flare on (LensCameraParams::flareReflections).
// `response`: spectral transport's film (RenderSettings::filmResponse), each
// path at its own wavelengths as a camera sample's; none: RGB. `threads` 0:
// all cores. `withVariance`: fill FlareImage::variance (else it stays empty).
FlareImage flareLightPass(const LensCamera& camera, std::span<const PunctualLight> lights,
                          std::uint64_t paths, std::uint64_t seed, const FilmResponse* response = nullptr,
                          int threads = 0, bool withVariance = false, const FlareScene& scene = {});

}  // namespace lensrt
