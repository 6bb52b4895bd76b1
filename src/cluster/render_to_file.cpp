#include "cluster/render_to_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/film_colour.h"
#include "api/output_file.h"
#include "api/render_request.h"
#include "api/sensor_readout.h"
#include "cluster/checkpoint.h"
#include "cluster/distributed_render.h"
#include "cluster/interrupt.h"
#include "core/error.h"
#include "image/image_io.h"
#include "image/spp_channel.h"
#include "render/progress.h"

namespace lensrt {
namespace {

// --crop or --tile: the part of the frame to render.
PixelRegion partOfFrame(const FileRender& job, int width, int height) {
  const PixelRegion frame = PixelRegion::wholeFrame(width, height);
  if (job.tile) {
    if (job.tile->count > height)
      throw UsageError("--tile",
                       fmt::format("{} tiles is more than the image's {} rows", job.tile->count, height));
    return frameStrip(job.tile->index, job.tile->count, width, height);
  }
  if (job.crop) {
    const PixelRegion& crop = *job.crop;
    if (!frame.contains(crop))
      throw UsageError("--crop",
                       fmt::format("{},{},{},{} is not inside the {}x{} image (X1 and Y1 at most {} and {})",
                                   crop.x0, crop.x1, crop.y0, crop.y1, width, height, width, height));
    return crop;
  }
  return frame;
}

}  // namespace

int renderToFile(const FileRender& givenJob, Cluster& cluster) {
  // Under MPI, rank 0 alone reads and writes the output and speaks; the
  // other ranks load the scene, make the camera and render what it sends.
  const bool shared = cluster.size() > 1, leader = cluster.isMain();
  FileRender args = givenJob;
  if (!leader) args.quiet = true;
  // 1. Options.
  SceneOptions& sceneOptions = args.scene;
  sceneOptions.quiet = args.quiet;
  RenderSettings& settings = args.settings;
  // Everything that can be checked without rendering is checked first, so
  // that a long render never ends in an error.
  std::error_code ec;
  if (leader) noteCreatedFolder(checkOutputFile(args.output), args.quiet);
  if (leader) checkRawOutput(args.raw);
  if (leader && args.display) checkDisplayTransform(args.output, *args.display);
  const bool exr = std::filesystem::path(args.output).extension() == ".exr";
  // A preview's 8 bits mean sRGB; other spaces' numbers would show wrong colours.
  if (!exr && args.camera.outputSpace != "srgb")
    throw UsageError("--output-space", args.camera.outputSpace + " needs an .exr output (" + args.output +
                                           " is a preview, whose colours are sRGB)");
  if ((args.checkpointSeconds > 0 || !args.resume.empty()) && !exr)
    throw UsageError("--checkpoint/--resume",
                     "need an .exr output (-o OUT.exr), the image that is continued");
  if (leader && !args.resume.empty() && !std::filesystem::exists(args.resume, ec))
    throw InputError(args.resume, "no such checkpoint");
  const std::string& envFile = sceneOptions.environment.file;
  if (!envFile.empty() && !std::filesystem::exists(envFile, ec))
    throw InputError(envFile, "environment map not found");
  if (!envFile.empty() && !std::filesystem::is_regular_file(envFile, ec))
    throw InputError(envFile, "the environment map is not a regular file");
  if (!envFile.empty()) checkImageReader(envFile);  // before the scene loads

  // Warnings wait until the scene and camera are set up, so that a run that
  // fails there prints its one error line alone.
  std::vector<std::string> held;
  bool holding = true;
  const auto print = [&](const std::string& message) {
    if (!args.quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", args.scene.scene, message);
  };
  Warnings warnings([&](const std::string& message) {
    if (holding)
      held.push_back(message);
    else
      print(message);
  });

  // 2. Scene, lights, camera, render.
  const RenderJob job =
      args.loaded ? RenderJob(args.loaded, sceneOptions, warnings) : RenderJob(sceneOptions, warnings);
  checkImageFitsInMemory(job.width(), job.height(), filmChannels(settings.aovs).size());
  const PixelRegion region = partOfFrame(args, job.width(), job.height());
  settings.region = region;
  const std::unique_ptr<Camera> camera = job.makeCamera(args.camera, warnings);
  settings.timing = job.shutterTiming(args.camera, warnings);
  const FilmColour colour = filmColour(args.camera, job.dominantLightColour(), warnings);
  const std::optional<SensorReadout> readout = sensorReadout(args.camera, camera->film(), colour.camera);
  settings.filmResponse = colour.response;
  ImageMetadata identity = job.identity(*camera, settings);
  addSensorIdentity(identity, readout);
  // The running sums live on rank 0 alone: the other ranks get strips.
  std::optional<FilmState> leaderState;
  if (leader) {
    leaderState = args.resume.empty() ? FilmState(region, settings.aovs)
                                      : readCheckpoint(args.resume, identity, region);
    if (leaderState->samplesDone() > settings.samplesPerPixel)
      throw UsageError("--spp",
                       fmt::format("{} has {} samples per pixel already, more than --spp {}", args.resume,
                                   leaderState->samplesDone(), settings.samplesPerPixel));
  }

  holding = false;
  for (const std::string& message : held) print(message);
  if (shared) {
    // Every rank is set up: go on together, or stop together with the first error.
    if (const auto failure = setUpTogether(cluster, args.scene.scene, identity)) {
      if (leader)
        fmt::print(stderr, "lensrt: error: rank {} of {}: {}\n", failure->rank, cluster.size(),
                   failure->line);
      return failure->status;
    }
  }
  if (!leader) {
    const InterruptHandler interrupt;
    workForMain(cluster, *camera, job.integrator(), settings, [&] { return interrupt.signal(); });
    return interrupt.signal() ? interrupt.exitStatus() : 0;
  }
  FilmState& state = *leaderState;
  // The flare light pass, once, for every image this process writes.
  settings.flareLight = job.flareLight(*camera, settings);

  // Passes, checkpoints and signals (the handlers only while rendering).
  const InterruptHandler interrupt;
  const auto started = std::chrono::steady_clock::now();
  auto lastCheckpoint = started;
  GatherCost gather;  // under MPI, once the render is done
  // The metadata of an image to write; with --noise on, the sensor reads it out first.
  const auto metadataOf = [&](RenderJobResult& r) {
    ImageMetadata m = job.metadata(*camera, settings, r, args.commandLine);
    if (readout) readOut(*readout, r.output.image, m, settings.seed, warnings);
    m["lensrt:spp_requested"] = std::to_string(settings.samplesPerPixel);
    if (shared) m["lensrt:mpi_ranks"] = std::to_string(cluster.size());
    if (gather.bytes > 0) {
      m["lensrt:gather_seconds"] = fmt::format("{:.3f}", gather.seconds);
      m["lensrt:gather_bytes"] = std::to_string(gather.bytes);
    }
    return m;
  };
  PassControl control;
  control.stopRequested = [&] { return interrupt.signal() != 0; };
  if (args.checkpointSeconds > 0)
    control.afterPass = [&](const FilmState& s) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - lastCheckpoint).count() < args.checkpointSeconds) return;
      RenderJobResult partial;
      partial.output = renderOutput(*camera, s, settings.flareLight.get());
      partial.seconds = std::chrono::duration<double>(now - started).count();
      const ImageMetadata metadata = metadataOf(partial);
      writeCheckpoint(args.output, s, partial.output.image, metadata);
      lastCheckpoint = std::chrono::steady_clock::now();
    };
  bool finished = false;
  int rankSignal = 0;  // a signal another rank received
  RenderJobResult result;
  if (shared) {
    {
      const int remaining = std::max(0, settings.samplesPerPixel - state.samplesDone());
      Progress progress(region.pixelCount() * std::uint64_t(remaining),
                        Progress::styleFor(stderr, args.quiet));
      finished = renderAcrossRanks(cluster, *camera, job.integrator(), settings, state, control, &progress,
                                   rankSignal, &gather);
    }
    result.output = renderOutput(*camera, state, settings.flareLight.get());
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  } else {
    result = job.renderPasses(*camera, settings, state, control, args.quiet, finished);
  }

  // 3. Write: with the running sums when it can be continued.
  {
    ImageMetadata metadata = metadataOf(result);
    ImageWriteOptions options;
    options.display = args.display;
    if (args.display) {
      std::string shown = args.display->display.empty() ? "(default display)" : args.display->display;
      shown += " / ";
      shown += args.display->view.empty() ? "(default view)" : args.display->view;
      metadata["lensrt:ocio_display_view"] = shown;
    }
    if (args.checkpointSeconds > 0 || !finished)
      writeCheckpoint(args.output, state, result.output.image, metadata, options);
    else
      writeOutputImage(args.output, result.output.image, metadata, options);
    if (!args.raw.file.empty() && finished)
      writeRawOutput(args.raw, result.output.image, readout, *camera, args.camera, colour.camera);
  }
  if (result.output.droppedSamples > 0 && !args.quiet)
    fmt::print(stderr, "lensrt: warning: {}: {} samples with NaN or infinite radiance were dropped\n",
               args.scene.scene, result.output.droppedSamples);
  if (!finished) {
    if (!args.quiet)
      fmt::print(stderr, "lensrt: interrupted: wrote {} with {} of {} spp (continue with --resume {})\n",
                 args.output, state.samplesDone(), settings.samplesPerPixel, args.output);
    return interrupt.signal() ? interrupt.exitStatus() : 128 + rankSignal;
  }
  if (!args.quiet)
    fmt::print(stderr, "lensrt: wrote {} ({}x{}, {} spp, {:.2f} s, {})\n", args.output,
               result.output.image.width, result.output.image.height,
               adaptiveSppSummary(result.output.image).value_or(std::to_string(settings.samplesPerPixel)),
               result.seconds, camera->describe());
  return 0;
}

}  // namespace lensrt
