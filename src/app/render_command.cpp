// `lensrt render SCENE -o OUT`: path-trace a glTF scene to an image.
#include <fmt/core.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "app/camera_options.h"
#include "app/command.h"
#include "app/render_options.h"
#include "core/error.h"
#include "image/image_io.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/progress.h"
#include "render/renderer.h"
#include "scene/camera_selection.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

struct RenderArgs {
  std::string scene;
  std::string output;
  int spp = 16;
  std::string resolution;
  int maxDepth = 8;
  int threads = 0;
  std::uint64_t seed = 0;
  std::string cameraNode;
  int sceneIndex = -1;
  std::string environment;
  std::vector<std::string> aovs;
  int tileSize = 16;
  bool quiet = false;
  CameraOptions camera;
};

constexpr int kDefaultWidth = 640, kDefaultHeight = 360;

// Everything that can be checked without rendering is checked first, so that
// a long render never ends in an error.
void checkOutput(const std::filesystem::path& out) {
  if (!isWritableImageExtension(out))
    throw CLI::ValidationError("-o: unknown image extension '" + out.extension().string() +
                               "' (use .exr for the full result, .png or .jpg for a preview)");
  std::filesystem::path dir = out.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError(out.string(), "the output directory " + dir.string() + " does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw InputError(out.string(), "the output directory " + dir.string() + " is not writable");
  if (std::filesystem::is_directory(out, ec)) throw InputError(out.string(), "is a directory");
}

Environment makeEnvironment(const EnvironmentSpec& spec) {
  if (spec.constant) return Environment::constant(*spec.constant);
  if (spec.file.empty()) return Environment();
  const Image map = readImage(spec.file);
  try {
    return Environment::latLong(map);
  } catch (const std::invalid_argument& e) {
    throw InputError(spec.file, e.what());
  }
}

int runRender(const RenderArgs& args, const CommandContext& context) {
  // 1. Options.
  const std::optional<Resolution> res =
      args.resolution.empty() ? std::nullopt : std::optional(parseResolution(args.resolution));
  const EnvironmentSpec envSpec =
      args.environment.empty() ? EnvironmentSpec{} : parseEnvironment(args.environment);
  const AovSelection aovs = parseAovs(args.aovs);
  checkOutput(args.output);
  if (!args.environment.empty() && !envSpec.file.empty() && !std::filesystem::is_regular_file(envSpec.file))
    throw InputError(envSpec.file, "environment map not found");

  Warnings warnings([&](const std::string& message) {
    if (!args.quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", args.scene, message);
  });

  // 2. Scene, camera, lights.
  SceneDesc desc = loadGltf(args.scene, args.sceneIndex, warnings);
  const float defaultAspect = float(kDefaultWidth) / float(kDefaultHeight);
  const float aspectGuess = res && res->height > 0 ? float(res->width) / float(res->height) : defaultAspect;
  CameraDesc cam = selectCamera(desc, args.cameraNode, aspectGuess);
  // Without --res (or with a width only) the height follows the glTF camera's
  // aspect ratio when it has one, else 16:9.
  const int width = res ? res->width : kDefaultWidth;
  int height = res && res->height > 0 ? res->height : 0;
  if (height == 0) {
    const float aspect = cam.aspectRatio && *cam.aspectRatio > 0 ? *cam.aspectRatio : defaultAspect;
    height = std::max(1, int(std::lround(float(width) / aspect)));
  }
  if (!res || res->height == 0) cam = selectCamera(desc, args.cameraNode, float(width) / float(height));
  const Environment environment = makeEnvironment(envSpec);

  // The scene is built before the camera: --focus auto asks it what the
  // focus pixel sees.
  const RenderScene scene(std::move(desc));
  const HitDistance hitDistance = [&scene](const Ray& ray) -> std::optional<double> {
    const std::optional<SurfaceHit> hit = scene.intersect(ray);
    return hit ? std::optional<double>(hit->t) : std::nullopt;
  };
  std::unique_ptr<Camera> camera;
  try {
    FilmGeometry raster;
    raster.width = width;
    raster.height = height;
    camera = makeCamera(args.camera, cam, raster, hitDistance, warnings);
  } catch (const std::invalid_argument& e) {
    throw InputError(args.scene, "camera '" + cam.name + "': " + e.what());
  }
  const MaterialTable materials(scene.desc());
  const LightSet lights(materials, environment, scene.bounds());
  if (lights.empty() && !args.quiet)
    warnings.warn(
        "the scene has no lights, emissive surfaces or environment: the image will be black "
        "(try --env constant:1)");
  IntegratorSettings integratorSettings;
  integratorSettings.maxDepth = args.maxDepth;
  const Integrator integrator(scene, materials, lights, environment, integratorSettings);

  // 3. Render.
  RenderSettings settings;
  settings.samplesPerPixel = args.spp;
  settings.seed = args.seed;
  settings.threads = args.threads;
  settings.tileSize = args.tileSize;
  settings.aovs = aovs;
  const auto start = std::chrono::steady_clock::now();
  RenderOutput out;
  {
    Progress progress(std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(args.spp),
                      Progress::styleFor(stderr, args.quiet));
    out = renderImage(*camera, integrator, settings, &progress);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // 4. Write.
  ImageMetadata metadata{
      {"lensrt:camera", camera->describe()},
      {"lensrt:spp", std::to_string(args.spp)},
      {"lensrt:seed", std::to_string(args.seed)},
      {"lensrt:max_depth", std::to_string(args.maxDepth)},
      {"lensrt:environment", environment.describe()},
      {"lensrt:render_seconds", fmt::format("{:.3f}", seconds)},
      {"lensrt:version", LENSRT_VERSION},
      {"lensrt:command_line", context.commandLine},
      {"lensrt:nan_samples", std::to_string(out.droppedSamples)},
      {"lensrt:camera_ray_efficiency", fmt::format("{:.4f}", out.cameraRayEfficiency())},
  };
  metadata.merge(cameraMetadata(*camera));
  writeImage(args.output, out.image, metadata);
  if (out.droppedSamples > 0 && !args.quiet)
    fmt::print(stderr, "lensrt: warning: {}: {} samples with NaN or infinite radiance were dropped\n",
               args.scene, out.droppedSamples);
  if (!args.quiet)
    fmt::print(stderr, "lensrt: wrote {} ({}x{}, {} spp, {:.2f} s, {})\n", args.output, width, height,
               args.spp, seconds, camera->describe());
  return 0;
}

}  // namespace

CommandAction addRenderCommand(CLI::App& app, const CommandContext& context) {
  CLI::App* cmd = app.add_subcommand("render",
                                     "Path-trace a glTF 2.0 scene (.gltf/.glb) to an image.\n"
                                     "Example: lensrt render scenes/dof_row.gltf --spp 64 --res 640x360 "
                                     "--aov depth,variance -o out/dof_row.exr");
  auto args = std::make_shared<RenderArgs>();
  cmd->add_option("scene", args->scene, "glTF scene file (.gltf or .glb), e.g. scenes/dof_row.gltf")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "output image: .exr (linear float, all channels and metadata) or .png/.jpg (sRGB preview), "
                  "e.g. -o out/a.exr")
      ->required();
  cmd->add_option("--spp", args->spp, "samples per pixel (>= 1), e.g. --spp 64")
      ->check(CLI::Range(1, 1 << 24))
      ->capture_default_str();
  cmd->add_option(
         "--res", args->resolution,
         "image size in pixels WIDTHxHEIGHT, e.g. --res 640x360; a WIDTH alone takes the height from the "
         "glTF camera's aspect ratio (default 640 wide, height from the camera's aspect ratio or 360)")
      ->check([](const std::string& s) { return checkResolution(s); });
  cmd->add_option(
         "--max-depth", args->maxDepth,
         "maximum scattering events per path (0: emitters only, 1: direct light), e.g. --max-depth 8")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "worker threads (0: all cores), e.g. --threads 4")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; same seed, same image on any machine, e.g. --seed 7")
      ->capture_default_str();
  cmd->add_option(
      "--camera-node", args->cameraNode,
      "camera to render: a glTF node name or index, e.g. --camera-node 3 (default: the scene's first "
      "camera, else a view framing the scene)");
  cmd->add_option(
         "--scene-index", args->sceneIndex,
         "which glTF scene to render (0-based; default: the file's default scene), e.g. --scene-index 1")
      ->check(CLI::Range(-1, 1 << 20));
  cmd->add_option(
         "--env", args->environment,
         "environment light: constant:V or constant:R,G,B radiance in W/(sr m^2), or a lat-long .exr/.hdr "
         "map (centre = -Z, +Y up), e.g. --env constant:1 (default: black)")
      ->check([](const std::string& s) { return checkEnvironment(s); });
  cmd->add_option(
         "--aov", args->aovs,
         "extra EXR channels, comma separated: depth (depth.Z, metres), normal (normal.X/Y/Z, world), "
         "albedo (albedo.R/G/B), variance (variance.R/G/B of the pixel mean), e.g. --aov depth,variance")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal", "albedo", "variance"}));
  cmd->add_option("--tile", args->tileSize, "tile size in pixels for scheduling (does not change the image)")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  addCameraOptions(*cmd, args->camera);
  cmd->add_flag("-q,--quiet", args->quiet, "no progress, warnings or summary on stderr (errors still print)");
  return [args, context]() { return runRender(*args, context); };
}

}  // namespace lensrt
