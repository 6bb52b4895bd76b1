// Helpers for the render-level camera tests: emitters built in code, a direct
// render through the whole renderer, edge profiles and the `lensrt` binary.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "image/image.h"
#include "render/environment.h"
#include "scene/scene_desc.h"

namespace lensrt::test {

// An emissive rectangle [x0, x1] x [y0, y1] (camera space, metres) in the
// plane z = -distance, facing the camera (+Z), with grey radiance `emission`.
SceneDesc rectangleScene(float x0, float x1, float y0, float y1, float distance, float emission);

// A square of side `size` centred on the -Z axis at `distance`.
SceneDesc squareScene(float distance, float size, float emission);

struct RenderedImage {
  Image image;
  int red = 0;         // channel index of R
  int varianceR = -1;  // channel of variance.R, when asked for
};

// Emitters and the environment seen directly plus one bounce, `spp` samples
// per pixel, seed 3.
RenderedImage renderScene(SceneDesc desc, const Camera& camera, const Environment& env, int spp,
                          bool variance = false);

// A channel's centroid in frame pixels (a region's origin included).
struct Centroid {
  double x = 0, y = 0;
};
Centroid centroid(const Image& img, const char* channel);

// Mean of channel R over each column: a vertical edge's profile.
std::vector<double> columnProfile(const RenderedImage& img);

// Width in pixels between where `profile` first rises through `lo` (from the
// left) and last rises through `hi` (from the right), by linear
// interpolation between pixel centres; the profile runs from 0 (left) to 1.
double riseWidth(const std::vector<double>& profile, double lo = 0.1, double hi = 0.9);

// The fraction of a uniform disk of radius 1 left of the line x = u: the
// edge spread function of a uniform blur disk (the circular segment's area).
double diskEdgeSpread(double u);

// Runs the built `lensrt` with `args`; returns its exit status. Output goes
// to `log` (stdout and stderr).
int runLensrt(const std::vector<std::string>& args, const std::string& log);

}  // namespace lensrt::test
