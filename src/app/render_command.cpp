// `lensrt render SCENE -o OUT`: path-trace a glTF scene to an image.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/camera_options.h"
#include "api/output_file.h"
#include "api/raw_output.h"
#include "api/render_job.h"
#include "api/render_options.h"
#include "api/render_request.h"
#include "api/sensor_readout.h"
#include "app/camera_flags.h"
#include "app/command.h"
#include "app/option_checks.h"
#include "app/render_flags.h"
#include "cluster/checkpoint.h"
#include "cluster/cluster.h"
#include "cluster/distributed_render.h"
#include "cluster/interrupt.h"
#include "core/error.h"

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
  EnvironmentArgs environment;
  SceneAccessArgs access;
  std::vector<std::string> aovs;
  int tileSize = 16;
  std::string crop;
  std::string tile;
  RawOutputOptions raw;
  double checkpointSeconds = 0;  // 0: no checkpoints
  std::string resume;
  bool quiet = false;
  CameraOptions camera;
};

// --crop X0,X1,Y0,Y1 or --tile I/N: the part of the frame to render.
PixelRegion partOfFrame(const RenderArgs& args, int width, int height) {
  const PixelRegion frame = PixelRegion::wholeFrame(width, height);
  if (!args.tile.empty()) {
    const auto slash = args.tile.find('/');
    const int index = std::stoi(args.tile.substr(0, slash)), count = std::stoi(args.tile.substr(slash + 1));
    if (count > height)
      throw CLI::ValidationError("--tile",
                                 fmt::format("{} tiles is more than the image's {} rows", count, height));
    return frameStrip(index, count, width, height);
  }
  if (!args.crop.empty()) {
    int v[4];
    std::sscanf(args.crop.c_str(), "%d,%d,%d,%d", &v[0], &v[1], &v[2], &v[3]);
    const PixelRegion crop{v[0], v[1], v[2], v[3]};
    if (!frame.contains(crop))
      throw CLI::ValidationError(
          "--crop", fmt::format("{} is not inside the {}x{} image (X1 and Y1 at most {} and {})", args.crop,
                                width, height, width, height));
    return crop;
  }
  return frame;
}

std::string checkCrop(const std::string& text) {
  int v[4];
  char end = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &end) != 4)
    return "expected X0,X1,Y0,Y1 in pixels, e.g. --crop 0,320,0,180";
  if (v[0] < 0 || v[2] < 0 || v[1] <= v[0] || v[3] <= v[2])
    return "expected 0 <= X0 < X1 and 0 <= Y0 < Y1 (X1, Y1 exclusive), got " + text;
  return "";
}

std::string checkTile(const std::string& text) {
  int index = 0, count = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &end) != 2)
    return "expected I/N (tile I of N, I from 0), e.g. --tile 0/8";
  if (count < 1 || index < 0 || index >= count) return "expected 0 <= I < N, got " + text;
  return "";
}

int runRender(const RenderArgs& givenArgs, const CommandContext& context) {
  // Under MPI, rank 0 alone reads and writes the output and speaks; the
  // other ranks load the scene, make the camera and render what it sends.
  Cluster& cluster = *context.cluster;
  const bool shared = cluster.size() > 1, leader = cluster.isMain();
  RenderArgs args = givenArgs;
  if (!leader) args.quiet = true;
  // 1. Options.
  SceneOptions sceneOptions;
  sceneOptions.scene = args.scene;
  sceneOptions.sceneIndex = args.sceneIndex;
  sceneOptions.cameraNode = args.cameraNode;
  if (!args.resolution.empty()) sceneOptions.resolution = parseResolution(args.resolution);
  sceneOptions.environment = environmentSpec(args.environment);
  sceneOptions.maxDepth = args.maxDepth;
  sceneOptions.quiet = args.quiet;
  sceneOptions.limits = sceneReadLimits(args.access);
  RenderSettings settings;
  settings.samplesPerPixel = args.spp;
  settings.seed = args.seed;
  settings.threads = args.threads;
  settings.tileSize = args.tileSize;
  settings.aovs = parseAovs(args.aovs);
  // Everything that can be checked without rendering is checked first, so
  // that a long render never ends in an error.
  std::error_code ec;
  if (leader) noteCreatedFolder(checkOutputFile(args.output), args.quiet);
  if (leader) checkRawOutput(args.raw);
  const bool exr = std::filesystem::path(args.output).extension() == ".exr";
  if ((args.checkpointSeconds > 0 || !args.resume.empty()) && !exr)
    throw CLI::ValidationError("--checkpoint/--resume",
                               "need an .exr output (-o OUT.exr), the image that is continued");
  if (leader && !args.resume.empty() && !std::filesystem::exists(args.resume, ec))
    throw InputError(args.resume, "no such checkpoint");
  const std::string& envFile = sceneOptions.environment.file;
  if (!envFile.empty() && !std::filesystem::exists(envFile, ec))
    throw InputError(envFile, "environment map not found");
  if (!envFile.empty() && !std::filesystem::is_regular_file(envFile, ec))
    throw InputError(envFile, "the environment map is not a regular file");

  // Warnings wait until the scene and camera are set up, so that a run that
  // fails there prints its one error line alone.
  std::vector<std::string> held;
  bool holding = true;
  const auto print = [&](const std::string& message) {
    if (!args.quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", args.scene, message);
  };
  Warnings warnings([&](const std::string& message) {
    if (holding)
      held.push_back(message);
    else
      print(message);
  });

  // 2. Scene, lights, camera, render.
  const RenderJob job(sceneOptions, warnings);
  checkImageFitsInMemory(job.width(), job.height(), filmChannels(settings.aovs).size());
  const PixelRegion region = partOfFrame(args, job.width(), job.height());
  settings.region = region;
  const std::unique_ptr<Camera> camera = job.makeCamera(args.camera, warnings);
  const std::optional<SensorReadout> readout = sensorReadout(args.camera, camera->film());
  ImageMetadata identity = job.identity(*camera, settings);
  addSensorIdentity(identity, readout);
  // The running sums live on rank 0 alone: the other ranks get strips.
  std::optional<FilmState> leaderState;
  if (leader) {
    leaderState = args.resume.empty() ? FilmState(region, settings.aovs)
                                      : readCheckpoint(args.resume, identity, region);
    if (leaderState->samplesDone() > settings.samplesPerPixel)
      throw CLI::ValidationError(
          "--spp", fmt::format("{} has {} samples per pixel already, more than --spp {}", args.resume,
                               leaderState->samplesDone(), settings.samplesPerPixel));
  }

  holding = false;
  for (const std::string& message : held) print(message);
  if (shared) {
    // Every rank is set up: go on together, or stop together with the first error.
    if (const auto failure = setUpTogether(cluster, args.scene, identity)) {
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

  // Passes, checkpoints and signals (the handlers only while rendering).
  const InterruptHandler interrupt;
  const auto started = std::chrono::steady_clock::now();
  auto lastCheckpoint = started;
  GatherCost gather;  // under MPI, once the render is done
  // The metadata of an image to write; with --noise on, the sensor reads it out first.
  const auto metadataOf = [&](RenderJobResult& r) {
    ImageMetadata m = job.metadata(*camera, settings, r, context.commandLine);
    if (readout) readOut(*readout, r.output.image, m, settings.seed);
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
      partial.output = renderOutput(*camera, s);
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
    result.output = renderOutput(*camera, state);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  } else {
    result = job.renderPasses(*camera, settings, state, control, args.quiet, finished);
  }

  // 3. Write: with the running sums when it can be continued.
  {
    const ImageMetadata metadata = metadataOf(result);
    if (args.checkpointSeconds > 0 || !finished)
      writeCheckpoint(args.output, state, result.output.image, metadata);
    else
      writeOutputImage(args.output, result.output.image, metadata);
    if (!args.raw.file.empty() && finished)
      writeRawOutput(args.raw, result.output.image, readout, *camera, args.camera);
  }
  if (result.output.droppedSamples > 0 && !args.quiet)
    fmt::print(stderr, "lensrt: warning: {}: {} samples with NaN or infinite radiance were dropped\n",
               args.scene, result.output.droppedSamples);
  if (!finished) {
    if (!args.quiet)
      fmt::print(stderr, "lensrt: interrupted: wrote {} with {} of {} spp (continue with --resume {})\n",
                 args.output, state.samplesDone(), settings.samplesPerPixel, args.output);
    return interrupt.signal() ? interrupt.exitStatus() : 128 + rankSignal;
  }
  if (!args.quiet)
    fmt::print(stderr, "lensrt: wrote {} ({}x{}, {} spp, {:.2f} s, {})\n", args.output,
               result.output.image.width, result.output.image.height, args.spp, result.seconds,
               camera->describe());
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
      ->check(integerIn(1, 1 << 24, "samples per pixel"))
      ->capture_default_str();
  cmd->add_option(
         "--res", args->resolution,
         "image size in pixels WIDTHxHEIGHT, e.g. --res 640x360; a WIDTH alone takes the height from the "
         "glTF camera's aspect ratio (default 640 wide, height from the camera's aspect ratio or 360)")
      ->check([](const std::string& s) { return checkResolution(s); });
  cmd->add_option(
         "--max-depth", args->maxDepth,
         "maximum scattering events per path (0: emitters only, 1: direct light), e.g. --max-depth 8")
      ->check(integerIn(0, 1024, "scattering events per path"))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "worker threads (0: all cores), e.g. --threads 4")
      ->check(integerIn(0, 4096, "worker threads, 0 for all cores"))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; same seed, same image on any machine, e.g. --seed 7")
      ->check(integerIn<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  cmd->add_option(
      "--camera-node", args->cameraNode,
      "camera to render: a glTF node name or index, e.g. --camera-node 3 (default: the scene's first "
      "camera, else a view framing the scene)");
  cmd->add_option(
         "--scene-index", args->sceneIndex,
         "which glTF scene to render (0-based; default: the file's default scene), e.g. --scene-index 1")
      ->check(integerIn(0, 1 << 20, "0-based"));
  addEnvironmentOptions(*cmd, args->environment);
  addSceneAccessOptions(*cmd, args->access);
  cmd->add_option(
         "--aov", args->aovs,
         "extra EXR channels, comma separated: depth (depth.Z, metres), normal (normal.X/Y/Z, world), "
         "albedo (albedo.R/G/B), variance (variance.R/G/B of the pixel mean), e.g. --aov depth,variance")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal", "albedo", "variance"}));
  cmd->add_option("--tile-size", args->tileSize,
                  "tile size in pixels for scheduling threads (does not change the image)")
      ->check(integerIn(1, 4096, "pixels"))
      ->capture_default_str();
  auto* crop =
      cmd->add_option("--crop", args->crop,
                      "render only pixels X0 <= x < X1, Y0 <= y < Y1 of the frame into an EXR whose data "
                      "window places them (join parts with lensrt merge), e.g. --crop 0,320,0,180")
          ->check([](const std::string& s) { return checkCrop(s); });
  cmd->add_option(
         "--tile", args->tile,
         "render only tile I (from 0) of N: horizontal strips top to bottom, heights differing by at "
         "most a row (for job arrays; join with lensrt merge), e.g. --tile 0/8")
      ->check([](const std::string& s) { return checkTile(s); })
      ->excludes(crop);
  cmd->add_option(
      "--raw", args->raw.file,
      "also write the raw file a camera would: the colour filter mosaic (--cfa) as a 16-bit linear "
      "DNG that raw developers read (with --noise on the sensor's DN; else an image value of 1.0 "
      "at the white level 65535), e.g. --raw out/a.dng");
  cmd->add_option("--cfa", args->raw.cfa, "the raw file's colour filter pattern: RGGB, BGGR, GRBG or GBRG")
      ->check(CLI::IsMember({"RGGB", "BGGR", "GRBG", "GBRG"}))
      ->capture_default_str();
  cmd->add_option(
         "--checkpoint", args->checkpointSeconds,
         "every SECONDS, write the image so far to -o (atomically) with its running sums in OUT.sums, "
         "so that --resume can continue it exactly, e.g. --checkpoint 600")
      ->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--resume", args->resume,
                  "continue the checkpoint CHECKPOINT.exr (same scene, camera and settings) to --spp, e.g. "
                  "--resume out/a.exr");
  addCameraOptions(*cmd, args->camera);
  cmd->add_flag("-q,--quiet", args->quiet, "no progress, warnings or summary on stderr (errors still print)");
  return [args, context]() { return runRender(*args, context); };
}

}  // namespace lensrt
