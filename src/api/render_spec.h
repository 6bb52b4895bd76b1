// Everything a render is asked for, typed: what `lensrt render`'s flags and
// Python's Scene.render keywords fill through the option table
// (api/option_table.h), and all that api/render_plan.h needs. Below the
// table no setting is text to be parsed again.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "api/camera_spec.h"
#include "api/colour_spec.h"
#include "api/flare_spec.h"
#include "api/raw_output.h"
#include "api/render_options.h"
#include "api/sensor_spec.h"
#include "api/shutter_spec.h"
#include "core/transform.h"
#include "render/film.h"
#include "render/lights.h"
#include "render/pixel_region.h"

namespace lensrt {

// The scene file, which of its scenes, and what it may make lensrt read.
struct SceneFileSpec {
  std::string file;     // .gltf / .glb
  int sceneIndex = -1;  // -1: the file's default scene
  SceneAccessArgs access;
};

// When the shutter opens: --time SECONDS or --frame N at --fps.
struct TimeSpec {
  std::optional<double> seconds;
  std::optional<int> frame;
  double fps = 24.0;
  std::string animation;  // a name or a 0-based index; empty: every animation plays
  double atSeconds() const { return frame ? double(*frame) / fps : seconds.value_or(0.0); }
  // --aov flow's neighbouring frames lie this many seconds before and after
  // (--flow-step, else `--frames`' step); 0: one frame (1 / fps) with --frame.
  double flowStepSeconds = 0.0;
  // The seconds to the neighbouring frames flow compares; 0: a still frame
  // (flow is the motion over its shutter).
  double flowFrameSeconds() const { return flowStepSeconds > 0 ? flowStepSeconds : frame ? 1.0 / fps : 0.0; }
};

// The integrator and the samples.
struct SamplingSpec {
  int spp = 16;                 // with adaptive sampling, the most a pixel takes
  double noiseThreshold = 0.0;  // 0: every pixel takes spp samples
  std::optional<int> minSpp;    // none: adaptive sampling's default
  std::uint64_t seed = 0;
  int maxDepth = 8;
  LightSampling lightSampling = LightSampling::Tree;
  int threads = 0;  // 0: all cores
  int tileSize = 16;
};

struct RenderSpec {
  SceneFileSpec scene;
  TimeSpec time;
  std::string cameraNode;                    // empty: the first camera, else a view framing the scene
  std::optional<Transform> worldFromCamera;  // replaces the chosen camera's pose (Python's camera_to_world)
  std::optional<Resolution> resolution;      // none: 640 wide
  EnvironmentSpec environment;
  CameraSpec camera;
  ShutterSpec shutter;
  FlareSpec flare;
  ColourSpec colour;
  SensorSpec sensor;
  SamplingSpec sampling;
  AovSelection aovs;
  RawOutputOptions raw;
  std::optional<PixelRegion> crop;  // none: the whole frame
  // Horizontal strip `index` of `count` (top to bottom) instead of the frame.
  struct Strip {
    int index = 0, count = 1;
  };
  std::optional<Strip> tile;
};

// Adaptive sampling as the sampling spec asks for it (none without a noise
// threshold). Throws UsageError.
std::optional<AdaptiveSampling> adaptiveSampling(const SamplingSpec& sampling);

}  // namespace lensrt
