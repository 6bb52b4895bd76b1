// The light pass of lens flare (--flare on): small bright sources, which
// camera paths never find (punctual lights) or find only as rare heavy
// samples after a lens reflection (small emitters, the sun), sent through the
// full lens from their side (particle tracing,
// LensSystem::traceFromSceneWithFlare) and deposited on the film.
//
// The sources:
// - every punctual light: all its paths, the direct image (no reflection)
//   included, as camera paths never see a punctual light;
// - the emissive triangles that stay still during the shutter
//   (LightSet::stillEmitter), together one source, and the environment's
//   sun (Environment::hasSun): only their paths with at least one lens
//   reflection (ghosts and glare). Camera paths keep the direct image and
//   skip these sources where a camera ray that reflected in the lens meets
//   them (Integrator::trace's afterLensReflection), so no path counts twice;
// - the still point and spot lights' (isFlareLamp) light on the surfaces
//   the lens sees (FlareScene::litSurfaces): the ghosts of the bright patch
//   a lamp makes on a wall next to it, which camera paths find only as rare
//   heavy samples. Each path leaves the lamp in a direction uniform over its
//   sphere (a spot's: over its outer cone), meets the first surface, and is
//   reflected there toward its disc point by the surface's BSDF (if nothing
//   is in between); only its paths with a lens reflection count, and a
//   camera path whose ray reflected in the lens does not take these lamps'
//   light by next-event estimation at the first surface it meets, when
//   nothing is in the lamp's way (through a glass sheet it does: the pass's
//   rays stop at the sheet).
//
// Each path leaves its source toward a point spread uniformly over a disc
// 20% wider than the front element's clear aperture, on the front vertex
// plane. A punctual light sends it from its place (or, directional, across
// the disc); the emitters from a point uniform on a triangle picked by its
// flux toward the lens (luminance x area x the solid angle the disc
// subtends at its centroid, so that the bright small lamps in frame take
// the paths and the emitters behind the lens none); the sun from a direction
// in it picked as the environment's importance sampling would. A shadow ray
// from the disc point toward the source point (through the scene at the
// shutter's opening) decides whether the path starts: a source half hidden
// from the lens is half seen. Each path carries the flux through its share
// of the disc (radiance x cosines / the sampling densities), reflects or
// refracts through the lens with the camera's reflection limit, barrel and
// stop shape (with two reflections and no barrel each path makes one ghost,
// picked by its strength, or a lamp's direct image: FlareOptions::ghost;
// else it chooses at every surface, reflecting more often than R:
// FlareOptions::reflectionBoost; either way with the weights that keep the
// expected flux), and what reaches the film lands
// in the pixel it hits (a box filter, as the camera's samples), as film
// irradiance times the camera's exposure scale: the same units as the camera
// paths' image, to which it is added.
//
// Its noise is reported too: `variance` holds each pixel's variance of the
// estimate (the paths of a source are independent and alike, so it is
// sum d^2 - (sum d)^2 / paths over their deposits d, summed over the
// sources, and at least its 3 x 3 neighbourhood's mean, so that a pixel of a
// ghost that no path happened to reach does not claim none), which the
// variance AOV adds to the camera paths', so that a noise-aware diff weighs a
// lamp's image and its ghosts by their own noise. Only when asked for
// (`withVariance`): it takes three times the memory.
//
// Deterministic: the paths are cut into chunks of kFlareChunk, each with its
// own random stream keyed by (seed, source, chunk); the chunks run in
// parallel, and their deposits are summed in chunk order. So the image has
// the same bits whatever the thread count, and every tile, part or rank
// takes its pixels from the same full-frame image.
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
