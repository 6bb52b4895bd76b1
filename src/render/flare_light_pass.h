// The light pass of lens flare (--flare on): punctual lights, which camera
// paths never find, sent through the full lens from their side (particle
// tracing, LensSystem::traceFromSceneWithFlare) and deposited on the film.
// For each light, `paths` rays leave it toward points spread uniformly over a
// disc 20% wider than the front element's clear aperture, on the front
// vertex plane; each carries the flux through its share of the disc (the
// light's intensity over the squared distance times the cosine, or a
// directional light's irradiance) and reflects or refracts at every surface
// as the camera's flare paths do (the same reflection limit, barrel and stop
// shape). What reaches the film lands in the pixel it hits (a box filter, as
// the camera's samples), as film irradiance times the camera's exposure
// scale: the same units as the camera paths' image, to which it is added.
// Every path counts, the direct image (no reflection) included: camera paths
// never see a punctual light, so nothing is counted twice.
//
// Its noise is reported too: `variance` holds each pixel's variance of the
// estimate (the paths of a light are independent and alike, so it is
// sum d^2 - (sum d)^2 / paths over their deposits d, summed over the
// lights, and at least its 3 x 3 neighbourhood's mean, so that a pixel of a
// ghost that no path happened to reach does not claim none), which the
// variance AOV adds to the camera paths', so that a noise-aware diff weighs a
// lamp's image and its ghosts by their own noise. Only when asked for
// (`withVariance`): it takes three times the memory.
//
// Deterministic: the paths are cut into chunks of kFlareChunk, each with its
// own random stream keyed by (seed, light, chunk); the chunks run in
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

class FilmResponse;

inline constexpr std::uint64_t kFlareChunk = 4096;

struct FlareImage {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;    // row by row, the whole frame
  std::vector<Rgb> variance;  // of each pixel's estimate, the same layout
  const Rgb& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// `lights` in world space; a light behind the front vertex or pointing away
// (a spot's cone) adds nothing. The camera must have flare on
// (LensCameraParams::flareReflections). `response`: spectral transport's
// film (RenderSettings::filmResponse), each path at its own wavelengths as a
// camera sample's; none: RGB. `threads` 0: all cores. `withVariance`: fill
// FlareImage::variance (else it stays empty).
FlareImage flareLightPass(const LensCamera& camera, std::span<const PunctualLight> lights,
                          std::uint64_t paths, std::uint64_t seed, const FilmResponse* response = nullptr,
                          int threads = 0, bool withVariance = false);

}  // namespace lensrt
