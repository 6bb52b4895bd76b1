#include "app/render_flags.h"

#include "app/option_checks.h"
#include "core/error.h"

namespace lensrt {

SceneOptions sceneOptions(const SceneArgs& args, bool quiet) {
  SceneOptions o;
  o.scene = args.scene;
  o.sceneIndex = args.sceneIndex;
  o.cameraNode = args.cameraNode;
  if (!args.resolution.empty()) o.resolution = parseResolution(args.resolution);
  o.environment = environmentSpec(args.environment);
  o.maxDepth = args.maxDepth;
  const std::optional<LightSampling> sampling = parseLightSampling(args.lightSampler);
  if (!sampling)
    throw UsageError("--light-sampler", "expected tree or power, got '" + args.lightSampler + "'");
  o.lightSampling = *sampling;
  o.quiet = quiet;
  o.limits = sceneReadLimits(args.access);
  if (args.time && args.frame) throw UsageError("--frame", "give --time SECONDS or --frame N, not both");
  o.time.seconds = args.frame ? double(*args.frame) / args.fps : args.time.value_or(0.0);
  o.time.animation = args.animation;
  return o;
}

void addLightSamplerOption(CLI::App& cmd, SceneArgs& args) {
  cmd.add_option("--light-sampler", args.lightSampler,
                 "how next-event estimation picks a light: tree (a light tree, by what each light can give "
                 "the shading point: for many lights) or power (by power alone, wherever the point), e.g. "
                 "--light-sampler power")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return parseLightSampling(text) ? "" : "expected tree or power, got '" + text + "'";
          },
          "tree|power"))
      ->capture_default_str();
}

void addAnimationOptions(CLI::App& cmd, SceneArgs& args) {
  cmd.add_option("--time", args.time,
                 "when the shutter opens, in seconds of the glTF's animations, e.g. --time 1.5 (default 0)")
      ->check(numberIn(-1e9, 1e9, "seconds"));
  cmd.add_option("--frame", args.frame, "the same counted in frames of --fps, e.g. --frame 36")
      ->check(integerIn(-1000000000, 1000000000, "a frame number"));
  cmd.add_option("--fps", args.fps, "frames per second for --frame, e.g. --fps 30")
      ->check(numberIn(1e-3, 1e6, "frames per second"))
      ->capture_default_str();
  cmd.add_option("--animation", args.animation,
                 "which glTF animation plays: a name or a 0-based index (default: all of them)");
}

void addEnvironmentOptions(CLI::App& cmd, EnvironmentArgs& args) {
  cmd.add_option(
         "--env", args.environment,
         "environment light: constant:V or constant:R,G,B radiance in W/(sr m^2), a lat-long "
         "image (centre = -Z, +Y up: .exr/.hdr as linear light, .png/.jpg/.tif/.webp/... decoded from sRGB, "
         "log .dpx from Cineon), or none (the scene's own light alone), e.g. --env constant:1 "
         "(default: none when the scene's lights and emissive surfaces light it, else a uniform sky of "
         "radiance 1, with a notice saying why)")
      ->check([](const std::string& s) { return checkEnvironment(s); });
  cmd.add_option("--env-rotate", args.rotationDegrees,
                 "turn the environment about +Y by DEG degrees, counterclockwise seen from above (right-hand "
                 "rule): at 90 the map's centre moves from -Z to -X; e.g. --env-rotate 90 (default 0)")
      ->check(numberIn(-360.0, 360.0, "degrees"));
  cmd.add_option("--env-intensity", args.intensity,
                 "multiply the environment's radiance by K (constant, map or the default sky), e.g. "
                 "--env-intensity 0.5 (default 1)")
      ->check(numberIn(0.0, 1e9, "a radiance scale"));
}

void addSceneAccessOptions(CLI::App& cmd, SceneAccessArgs& args) {
  cmd.add_flag("--allow-external-files", args.allowExternalFiles,
               "let the scene read files outside its folder (absolute paths, '..', symbolic links out of "
               "it), naming each one read; only for scenes you trust (default: off, or "
               "LENSRT_ALLOW_EXTERNAL_FILES=1)")
      ->envname("LENSRT_ALLOW_EXTERNAL_FILES")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            try {
              CLI::detail::to_flag_value(text);
              return "";
            } catch (const std::exception&) {
              return "expected 1 (on) or 0 (off), e.g. LENSRT_ALLOW_EXTERNAL_FILES=1, got '" + text + "'";
            }
          },
          ""));
  cmd.add_option("--max-texture-memory", args.maxTextureMiB,
                 "MiB the scene's textures may take as held for rendering (16 bytes a texel), e.g. "
                 "--max-texture-memory 4096 (default: half this machine's memory)")
      ->check(integerIn<std::uint64_t>(1, std::uint64_t{1} << 40, "MiB"))
      ->capture_default_str();
}

void addAdaptiveOptions(CLI::App& cmd, AdaptiveArgs& args) {
  CLI::Option* threshold =
      cmd.add_option("--noise-threshold", args.noiseThreshold,
                     "adaptive sampling: a pixel stops once the relative standard error of its mean is "
                     "below this (dark pixels: of a floor of 0.05), between --min-spp and --spp samples, "
                     "e.g. --noise-threshold 0.01")
          ->check(numberFrom(0, "the relative standard error at which a pixel stops", true));
  cmd.add_option("--min-spp", args.minSpp,
                 "adaptive sampling: samples every pixel takes before it may stop (default 16), e.g. "
                 "--min-spp 32")
      ->check(integerIn(1, 1 << 24, "samples per pixel"))
      ->needs(threshold);
}

std::optional<AdaptiveSampling> adaptiveSampling(const AdaptiveArgs& args, int spp) {
  return lensrt::adaptiveSampling(args.noiseThreshold, args.minSpp, spp);
}

}  // namespace lensrt
