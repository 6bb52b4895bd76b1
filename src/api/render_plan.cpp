#include "api/render_plan.h"

#include <fmt/core.h>

#include "api/camera_framing.h"
#include "api/option_table.h"
#include "api/raw_output.h"
#include "api/render_request.h"
#include "core/error.h"
#include "render/film.h"

namespace lensrt {
namespace {

// The part of the frame the spec asks for: a strip, a crop or all of it.
PixelRegion partOfFrame(const RenderSpec& spec, int width, int height) {
  const PixelRegion frame = PixelRegion::wholeFrame(width, height);
  if (spec.tile) {
    if (spec.tile->count > height)
      throw UsageError("--tile",
                       fmt::format("{} tiles is more than the image's {} rows", spec.tile->count, height));
    return frameStrip(spec.tile->index, spec.tile->count, width, height);
  }
  if (spec.crop) {
    const PixelRegion& crop = *spec.crop;
    if (!frame.contains(crop))
      throw UsageError("--crop",
                       fmt::format("{},{},{},{} is not inside the {}x{} image (X1 and Y1 at most {} and {})",
                                   crop.x0, crop.x1, crop.y0, crop.y1, width, height, width, height));
    return crop;
  }
  return frame;
}

// What in this render depends on wavelengths (--spectral auto's rules read it).
WavelengthNeeds wavelengthNeeds(const RenderSpec& spec, const RenderJob& job,
                                const RenderJob::MadeCamera& made) {
  const ColourSpec& c = spec.colour;
  WavelengthNeeds n;
  n.cameraResponse = !c.sensorResponse.empty() && c.sensorResponse != kCie1931Response;
  n.colourSettings = c.whiteBalance.has_value() || c.outputSpace != ColorSpaceId::Srgb;
  n.sceneDispersion = job.sceneDisperses();
  // A lens with dispersion data traced with --dispersion on: the full lens's
  // lateral colour, the thin and thick lenses' axial colour. The full lens
  // traces wavelengths under flare for a single-layer coating's reflectance too.
  n.lensDispersion = made.camera->info().dispersion;
  n.flareCoatings = made.camera->tracesWavelengths() && !n.lensDispersion;
  n.diffraction = made.camera->diffracts();
  return n;
}

}  // namespace

SceneOptions sceneOptions(const RenderSpec& spec, bool quiet) {
  SceneOptions o;
  o.scene = spec.scene.file;
  o.sceneIndex = spec.scene.sceneIndex;
  o.limits = sceneReadLimits(spec.scene.access);
  o.time.seconds = spec.time.atSeconds();
  o.time.animation = spec.time.animation;
  o.time.spanSeconds = spec.shutter.spanSeconds();
  o.cameraNode = spec.cameraNode;
  o.worldFromCamera = spec.worldFromCamera;
  o.resolution = spec.resolution;
  o.environment = spec.environment;
  o.maxDepth = spec.sampling.maxDepth;
  o.lightSampling = spec.sampling.lightSampling;
  o.quiet = quiet;
  o.framingField = cameraFramingField(spec.camera);
  return o;
}

RenderPlan::RenderPlan(const RenderSpec& spec, Warnings& warnings, const PlanOptions& options)
    : spec_(spec), options_(options) {
  checkSpec(spec_, options.command);
  checkColourSpec(spec_.colour);
  const SceneOptions frame = sceneOptions(spec_, options.quiet);
  // A moving scene is posed over the time the frame records it.
  std::shared_ptr<const Scene> scene = options.scene;
  const double span = spec_.shutter.spanSeconds();
  if (scene && !scene->geometry().desc().pose.empty() && scene->options().time.spanSeconds != span) {
    if (options.repose) {
      scene = options.repose(span);
    } else {
      SceneLoadOptions again = scene->options();
      again.time.spanSeconds = span;
      scene = std::make_shared<const Scene>(again, warnings);
    }
  }
  job_ = scene ? std::make_unique<RenderJob>(scene, frame, warnings)
               : std::make_unique<RenderJob>(frame, warnings);
  checkImageFitsInMemory(job_->width(), job_->height(), filmChannels(spec_.aovs).size());
  exposure_ = cameraExposure(spec_.camera, spec_.shutter);

  base_.samplesPerPixel = spec_.sampling.spp;
  base_.adaptive = adaptiveSampling(spec_.sampling);
  base_.seed = spec_.sampling.seed;
  base_.threads = spec_.sampling.threads;
  base_.tileSize = spec_.sampling.tileSize;
  base_.aovs = spec_.aovs;
  base_.aovs.spp = base_.adaptive.has_value();
  base_.region = partOfFrame(spec_, job_->width(), job_->height());
  // The camera first: its errors (the lens, the focus) come before the
  // colour's and the shutter's notices.
  RenderJob::MadeCamera made = job_->makeCamera(spec_.camera, spec_.shutter, spec_.flare, warnings);
  base_.timing = job_->shutterTiming(spec_.shutter, warnings);
  if (spec_.aovs.flow)
    base_.flow = job_->motionFlow(*made.camera, spec_.camera, spec_.shutter, base_.timing,
                                  spec_.time.flowFrameSeconds());
  // The one place --spectral auto is resolved: the film below and every
  // shot's metadata follow this choice.
  transport_ = chooseTransport(spec_.colour.transport, wavelengthNeeds(spec_, *job_, made));
  ColourSpec colour = spec_.colour;
  colour.transport = transport_.spectral ? Transport::Spectral : Transport::Rgb;
  colour_ = filmColour(colour, job_->dominantLightColour(), warnings);
  base_.filmResponse = colour_.response;
  readout_ = sensorReadout(spec_.sensor, exposure_, made.camera->film(), colour_.camera);
  shot_ = finishShot(std::move(made), spec_.camera);
}

RenderPlan::~RenderPlan() = default;

PlannedShot RenderPlan::finishShot(RenderJob::MadeCamera made, const CameraSpec& camera) const {
  PlannedShot shot;
  shot.camera = std::move(made.camera);
  shot.settings = base_;
  if (made.flareLens && options_.lightPass)
    shot.settings.flareLight = job_->flareLight(*made.flareLens, base_);
  shot.identity = job_->identity(*shot.camera, shot.settings);
  addSensorIdentity(shot.identity, readout_);
  RenderSpec asShot = spec_;
  asShot.camera = camera;
  shot.identity["lensrt:options"] = optionsIdentity(asShot);
  return shot;
}

PlannedShot RenderPlan::shotOf(const CameraSpec& camera, Warnings& warnings) const {
  return finishShot(job_->makeCamera(camera, spec_.shutter, spec_.flare, warnings), camera);
}

ImageMetadata RenderPlan::finish(RenderJobResult& result, const PlannedShot& shot,
                                 const std::string& commandLine, Warnings& warnings) const {
  ImageMetadata m =
      job_->metadata(*shot.camera, exposure_, shot.settings, result, commandLine, shot.identity);
  if (readout_) readOut(*readout_, result.output.image, m, shot.settings.seed, warnings);
  m["lensrt:spp_requested"] = std::to_string(shot.settings.samplesPerPixel);
  m["lensrt:transport"] = transport_.description;
  return m;
}

void RenderPlan::writeRaw(const Image& image) const {
  if (spec_.raw.file.empty()) return;
  writeRawOutput(spec_.raw, image, readout_, *shot_.camera, spec_.colour.outputSpace, exposure_,
                 colour_.camera);
}

}  // namespace lensrt
