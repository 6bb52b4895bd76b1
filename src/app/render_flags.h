// The environment and scene-access flags of `lensrt render` and `lensrt
// compare` (the settings they fill are api/render_options.h's).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "api/render_job.h"
#include "api/render_options.h"
#include "render/adaptive_sampling.h"

namespace lensrt {

// The scene flags `lensrt render` and `lensrt compare` share: the file and its frame.
struct SceneArgs {
  std::string scene;
  std::string resolution;  // --res; empty: the default
  int maxDepth = 8;
  std::string lightSampler = "tree";  // --light-sampler
  std::string cameraNode;
  int sceneIndex = -1;
  EnvironmentArgs environment;
  SceneAccessArgs access;
  std::optional<double> time;  // --time SECONDS
  std::optional<int> frame;    // --frame N, at --fps
  double fps = 24.0;
  std::string animation;  // --animation NAME|INDEX
};

// The api's options of those flags (UsageError for a bad --res or --env).
SceneOptions sceneOptions(const SceneArgs& args, bool quiet);

void addEnvironmentOptions(CLI::App& command, EnvironmentArgs& args);
// --allow-external-files (or LENSRT_ALLOW_EXTERNAL_FILES=1) and --max-texture-memory MIB.
void addSceneAccessOptions(CLI::App& command, SceneAccessArgs& args);
// --light-sampler tree|power.
void addLightSamplerOption(CLI::App& command, SceneArgs& args);
// --time SECONDS, --frame N, --fps F and --animation NAME|INDEX.
void addAnimationOptions(CLI::App& command, SceneArgs& args);

// --noise-threshold E and --min-spp N (adaptive sampling; --spp is then the most).
struct AdaptiveArgs {
  double noiseThreshold = 0;  // 0: not given, every pixel takes --spp samples
  std::optional<int> minSpp;  // none: the default
};
void addAdaptiveOptions(CLI::App& command, AdaptiveArgs& args);
// The adaptive sampling they ask for (none without --noise-threshold);
// UsageError when --min-spp is above --spp.
std::optional<AdaptiveSampling> adaptiveSampling(const AdaptiveArgs& args, int spp);

}  // namespace lensrt
