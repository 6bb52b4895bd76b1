#include "api/render_job.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "api/film_colour.h"
#include "camera/lens_camera.h"
#include "core/constants.h"
#include "core/error.h"
#include "image/image_io.h"
#include "image/spp_channel.h"
#include "render/flare_light_pass.h"
#include "render/id_coverage.h"
#include "render/light_level.h"
#include "render/material_eval.h"
#include "render/progress.h"
#include "render/render_identity.h"
#include "scene/camera_selection.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {
constexpr int kDefaultWidth = 640, kDefaultHeight = 360;

// Asking for a camera or scene the file does not have is a wrong flag value
// (exit 2), not a broken file.
template <class F>
auto asFlagError(const char* flag, F&& f) {
  try {
    return f();
  } catch (const SelectionError& e) {
    throw UsageError(flag, e.file() + ": " + e.message());
  }
}
// A 32x18 grid of rays over the glTF camera's view (parallel ones for an
// orthographic camera): where the weak-light test looks.
std::vector<Ray> probeRays(const CameraDesc& camera, float aspect) {
  constexpr int kColumns = 32, kRows = 18;
  std::vector<Ray> rays;
  const float tanY = std::tan(0.5f * camera.yfov);
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      const float x = 2 * (i + 0.5f) / kColumns - 1, y = 1 - 2 * (j + 0.5f) / kRows;
      Ray r;
      if (camera.orthographic) {
        r.origin = camera.worldFromCamera.point(Vec3f{x * camera.ymag * aspect, y * camera.ymag, 0});
        r.direction = normalize(camera.worldFromCamera.vector(Vec3f{0, 0, -1}));
      } else {
        r.origin = camera.worldFromCamera.point(Vec3f{0, 0, 0});
        r.direction = normalize(camera.worldFromCamera.vector(Vec3f{x * tanY * aspect, y * tanY, -1}));
      }
      rays.push_back(r);
    }
  return rays;
}
}  // namespace

Environment makeEnvironment(const EnvironmentSpec& spec) {
  const auto adjusted = [&](const Environment& e) {
    const Environment scaled = spec.intensity == 1 ? e : e.scaled(float(spec.intensity));
    return spec.rotationDegrees == 0 ? scaled : scaled.rotatedAboutY(float(spec.rotationDegrees));
  };
  if (spec.constant) return adjusted(Environment::constant(*spec.constant));
  if (spec.file.empty()) return Environment();
  const Image map = readLinearImage(spec.file);
  try {
    return adjusted(Environment::latLong(map));
  } catch (const std::invalid_argument& e) {
    throw InputError(spec.file, e.what());
  }
}

Environment defaultEnvironment(const EnvironmentSpec& spec) {
  EnvironmentSpec sky = spec;
  sky.constant = Rgb{kDefaultSkyRadiance, kDefaultSkyRadiance, kDefaultSkyRadiance};
  return makeEnvironment(sky);
}

RenderJob::RenderJob(const SceneOptions& options, Warnings& warnings)
    : RenderJob(
          std::make_shared<const Scene>(
              SceneLoadOptions{options.scene, options.sceneIndex, options.limits, options.time}, warnings),
          options, warnings) {}

RenderJob::RenderJob(std::shared_ptr<const Scene> scene, const FrameOptions& options, Warnings& warnings)
    : scene_(std::move(scene)), frame_(options) {
  const std::optional<Resolution>& res = options.resolution;
  const SceneDesc& desc = scene_->geometry().desc();
  const float defaultAspect = float(kDefaultWidth) / float(kDefaultHeight);
  const float aspectGuess = res && res->height > 0 ? float(res->width) / float(res->height) : defaultAspect;
  // The field a framed view fits the scene to, at an aspect ratio.
  const auto framingYfov = [&options](float aspect) {
    return options.framingField && aspect > 0 ? options.framingField(aspect) : FramingField{};
  };
  gltfCamera_ = asFlagError("--camera-node", [&] {
    return selectCamera(desc, options.cameraNode, aspectGuess, framingYfov(aspectGuess));
  });
  // Without --res (or with a width only) the height follows the glTF camera's
  // aspect ratio when it has one, else 16:9.
  width_ = res ? res->width : kDefaultWidth;
  height_ = res && res->height > 0 ? res->height : 0;
  if (height_ == 0) {
    const float aspect =
        gltfCamera_.aspectRatio && *gltfCamera_.aspectRatio > 0 ? *gltfCamera_.aspectRatio : defaultAspect;
    height_ = std::max(1, int(std::lround(float(width_) / aspect)));
  }
  if (!res || res->height == 0)
    gltfCamera_ = asFlagError("--camera-node", [&] {
      const float aspect = float(width_) / float(height_);
      return selectCamera(desc, options.cameraNode, aspect, framingYfov(aspect));
    });
  if (options.worldFromCamera) gltfCamera_.worldFromCamera = *options.worldFromCamera;
  environment_ = std::make_unique<Environment>(makeEnvironment(options.environment));
  const RenderScene& geometry = scene_->geometry();
  const MaterialTable& materials = scene_->materials();
  lights_ = std::make_unique<LightSet>(materials, *environment_, geometry.bounds(), options.lightSampling);
  // Most glTF files leave the lighting to the viewer, which shows them under
  // a default environment; so does lensrt, rather than render black. A scene
  // whose own emitters are token ones (a few glowing parts) gets the sky too.
  const bool environmentGiven =
      options.environment.none || options.environment.constant || !options.environment.file.empty();
  if (!environmentGiven) {
    std::string why;
    if (lights_->empty()) {
      why = "the scene has no light source";
    } else {
      const std::vector<Ray> probes = probeRays(gltfCamera_, float(width_) / float(height_));
      const double skyIrradiance = kPi * kDefaultSkyRadiance;
      const std::optional<double> level = medianEmitterIrradiance(geometry, materials, probes);
      const bool punctual = std::any_of(desc.lights.begin(), desc.lights.end(),
                                        [](const PunctualLight& l) { return luminance(l.intensity) > 0; });
      const double fraction = punctual ? kWeakLightFraction : kWeakGlowFraction;
      if (level && *level < fraction * skyIrradiance)
        why = fmt::format(
            "the scene's own light is too weak to light it (what the camera sees gets {:.3g} W/m^2 from its "
            "{}, under {:g}% of the default sky's {:.4g}; --env none keeps its light alone)",
            *level, punctual ? "lights" : "emissive surfaces", 100 * fraction, skyIrradiance);
    }
    if (!why.empty()) {
      *environment_ = defaultEnvironment(options.environment);
      lights_ =
          std::make_unique<LightSet>(materials, *environment_, geometry.bounds(), options.lightSampling);
      defaultEnvironment_ = true;
      if (!lights_->empty() && !options.quiet)
        warnings.warn(fmt::format(
            "{}: lighting it with the default environment, a uniform sky of radiance {:g} (--env chooses "
            "another)",
            why, kDefaultSkyRadiance * options.environment.intensity));
    }
  }
  if (lights_->empty() && !options.quiet)
    warnings.warn(
        "the scene has no lights, emissive surfaces or environment: the image will be black "
        "(try --env constant:1)");
  IntegratorSettings integratorSettings;
  integratorSettings.maxDepth = options.maxDepth;
  integrator_ =
      std::make_unique<Integrator>(geometry, materials, *lights_, *environment_, integratorSettings);
}

RenderJob::~RenderJob() = default;

bool RenderJob::sceneDisperses() const {
  const std::vector<Material>& materials = scene_->geometry().desc().materials;
  return std::any_of(materials.begin(), materials.end(), isDispersiveVolume);
}

std::string RenderJob::environmentDescription() const {
  return (defaultEnvironment_ ? "default " : "") + environment_->describe();
}

RenderJob::MadeCamera RenderJob::makeCamera(const CameraSpec& camera, const ShutterSpec& shutter,
                                            const FlareSpec& flare, Warnings& warnings) const {
  return makeCamera(camera, shutter, flare, scene_->options().time.seconds, warnings);
}

RenderJob::MadeCamera RenderJob::makeCamera(const CameraSpec& camera, const ShutterSpec& shutter,
                                            const FlareSpec& flare, double timeSeconds,
                                            Warnings& warnings) const {
  const HitDistance hitDistance = [this](const Ray& ray) -> std::optional<double> {
    const std::optional<SurfaceHit> hit = scene_->geometry().intersect(ray);
    return hit ? std::optional<double>(hit->t) : std::nullopt;
  };
  try {
    FilmGeometry raster;
    raster.width = width_;
    raster.height = height_;
    const CameraRequest request{camera, shutter, flare, timeSeconds};
    MadeCamera made;
    made.camera = lensrt::makeCamera(request, gltfCamera_, raster, hitDistance, warnings, &made.flareLens);
    return made;
  } catch (const std::invalid_argument& e) {
    throw InputError(scene_->options().file, "camera '" + gltfCamera_.name + "': " + e.what());
  }
}

std::optional<ShutterTiming> RenderJob::shutterTiming(const ShutterSpec& shutter, Warnings& warnings) const {
  ShutterTiming timing = shutter.timing();
  if (scene_->geometry().desc().motionSteps > 0) {
    // The glTF camera's node moves (unless a pose replaced it): rays follow it.
    if (!gltfCamera_.motion.empty() && !frame_.worldFromCamera) {
      const Transform fromOpening = gltfCamera_.motion.front().inverse();
      for (const Transform& at : gltfCamera_.motion) timing.cameraSteps.push_back(at * fromOpening);
    }
    // The scene was loaded for the same span (the caller's SceneOptions).
    if (std::abs(timing.spanSeconds() - scene_->options().time.spanSeconds) >
        1e-9 * std::max(1.0, timing.spanSeconds()))
      throw UsageError("--shutter", fmt::format("the scene was loaded for motion over {:g} s, not {:g} s",
                                                scene_->options().time.spanSeconds, timing.spanSeconds()));
    return timing;
  }
  if (shutter.readoutSeconds > 0 || shutter.rampFraction > 0)
    warnings.warn(fmt::format(
        "{}: nothing in the scene moves, so the rolling shutter and shutter curve change "
        "nothing",
        scene_->geometry().desc().pose.empty() ? "the scene has no animation" : "over the shutter"));
  return std::nullopt;
}

RenderJobResult RenderJob::render(const Camera& camera, const RenderSettings& settings, bool quiet) const {
  const auto start = std::chrono::steady_clock::now();
  RenderJobResult result;
  {
    const FilmGeometry& film = camera.film();
    Progress progress(
        std::uint64_t(film.width) * std::uint64_t(film.height) * std::uint64_t(settings.samplesPerPixel),
        Progress::styleFor(stderr, quiet));
    result.output = renderImage(camera, *integrator_, settings, &progress);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

RenderJobResult RenderJob::renderPasses(const Camera& camera, const RenderSettings& settings,
                                        FilmState& state, const PassControl& control, bool quiet,
                                        bool& finished) const {
  const auto start = std::chrono::steady_clock::now();
  RenderJobResult result;
  {
    const int remaining = std::max(0, settings.samplesPerPixel - state.samplesDone());
    Progress progress(state.region().pixelCount() * std::uint64_t(remaining),
                      Progress::styleFor(stderr, quiet));
    finished = lensrt::renderPasses(camera, *integrator_, settings, state, &control, &progress);
  }
  result.output = renderOutput(camera, state, settings.flareLight.get());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::shared_ptr<const FlareImage> RenderJob::flareLight(const LensCamera& lens,
                                                        const RenderSettings& settings) const {
  // Every punctual light, the still emitters and the environment's sun; each
  // path's shadow ray says whether the scene hides its source from the lens.
  // The lamps' light on the scene where camera paths would take it, by
  // next-event estimation at their first vertex.
  const FlareScene sources{&scene_->geometry(), lights_.get(), environment_.get(),
                           frame_.maxDepth >= 1 ? &scene_->materials() : nullptr};
  const FilmGeometry& film = lens.film();
  const std::uint64_t paths =
      std::max<std::uint64_t>(65536, std::uint64_t(std::max(1, settings.samplesPerPixel)) *
                                         std::uint64_t(film.width) * std::uint64_t(film.height) / 10);
  return std::make_shared<const FlareImage>(
      flareLightPass(lens, scene_->geometry().desc().lights, paths, settings.seed,
                     settings.filmResponse.get(), settings.threads, settings.aovs.variance, sources));
}

ImageMetadata RenderJob::identity(const Camera& camera, const RenderSettings& settings) const {
  std::string aovs;
  for (const std::string& c : filmChannels(settings.aovs)) aovs += (aovs.empty() ? "" : ",") + c;
  // Adaptive sampling's settings decide which pixels stop (--spp does not:
  // a render resumed to more samples continues the same decisions).
  const std::string adaptive =
      settings.adaptive ? fmt::format(" noise_threshold={} min_spp={}", settings.adaptive->noiseThreshold,
                                      settings.adaptive->minSamples)
                        : std::string();
  return {
      {"lensrt:scene_sha256", scene_->digest(frame_.environment.file)},
      {"lensrt:camera", camera.describe()},
      {"lensrt:settings",
       fmt::format(
           "res={}x{} max_depth={} light_sampler={} environment={} channels={} transport={}{}{}{}", width_,
           height_, frame_.maxDepth, lightSamplingName(frame_.lightSampling), environment_->describe(), aovs,
           transportDescription(settings.filmResponse.get()), adaptive,
           scene_->geometry().desc().pose.empty() ? std::string() : " " + scene_->geometry().desc().pose,
           settings.timing ? " shutter=" + settings.timing->describe() : std::string())},
      {"lensrt:seed", std::to_string(settings.seed)},
  };
}

ImageMetadata RenderJob::metadata(const Camera& camera, const Exposure& exposure,
                                  const RenderSettings& settings, const RenderJobResult& result,
                                  const std::string& commandLine, const ImageMetadata& identity) const {
  const RenderOutput& out = result.output;
  const std::uint64_t pixels = std::uint64_t(out.image.width) * std::uint64_t(out.image.height);
  ImageMetadata metadata{
      {"lensrt:spp", std::to_string(pixels ? out.cameraSamples / pixels : 0)},
      {"lensrt:camera_samples", std::to_string(out.cameraSamples)},
      {"lensrt:blocked_camera_rays", std::to_string(out.blockedCameraRays)},
      {"lensrt:max_depth", std::to_string(frame_.maxDepth)},
      {"lensrt:environment", environmentDescription()},
      {"lensrt:render_seconds", fmt::format("{:.3f}", result.seconds)},
      {"lensrt:scene_seconds", fmt::format("{:.4f}", scene_->seconds())},
      {"lensrt:version", LENSRT_VERSION},
      {"lensrt:command_line", commandLine},
      {"lensrt:nan_samples", std::to_string(result.output.droppedSamples)},
      {"lensrt:camera_ray_efficiency", fmt::format("{:.4f}", result.output.cameraRayEfficiency())},
  };
  if (const std::optional<std::string> spp = adaptiveSppSummary(out.image)) {
    metadata["lensrt:spp"] = *spp;
    metadata["lensrt:samples_done"] = std::to_string(out.samplesDone);
  }
  if (!out.image.isWholeFrame())
    metadata["lensrt:region"] = PixelRegion{out.image.originX, out.image.originX + out.image.width,
                                            out.image.originY, out.image.originY + out.image.height}
                                    .describe();
  metadata.merge(cryptomatteMetadata(scene_->geometry().desc(), settings.aovs));
  metadata.insert(identity.begin(), identity.end());  // keys already set stay
  metadata.merge(cameraMetadata(camera, exposure));
  // The film's colour: the transport, and what its RGB means.
  const FilmResponse* response = settings.filmResponse.get();
  metadata["lensrt:spectral"] = response ? "on" : "off";
  if (response) {
    metadata["lensrt:sensor_response"] = response->info().response;
    metadata["lensrt:white_balance"] = response->info().whiteBalance;
    metadata["lensrt:output_space"] = response->info().outputSpace;
    if (response->info().chromaticities.empty())
      metadata.erase("chromaticities");
    else
      metadata["chromaticities"] = response->info().chromaticities;
  }
  return metadata;
}

}  // namespace lensrt
