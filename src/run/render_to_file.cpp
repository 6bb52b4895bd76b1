#include "run/render_to_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/frame_camera.h"
#include "api/option_table.h"
#include "api/output_file.h"
#include "api/render_plan.h"
#include "api/text_file.h"
#include "core/error.h"
#include "image/flo_io.h"
#include "image/image_io.h"
#include "image/spp_channel.h"
#include "render/progress.h"
#include "run/checkpoint.h"
#include "run/distributed_render.h"
#include "run/interrupt.h"

namespace lensrt {
int renderToFile(const FileRender& givenJob, MpiJob& mpi) {
  // Under MPI, rank 0 alone reads and writes the output and speaks; the
  // other ranks load the scene, make the camera and render what it sends.
  const bool shared = mpi.size() > 1, leader = mpi.isMain();
  FileRender args = givenJob;
  if (!leader) args.quiet = true;
  // 1. Options.
  const RenderSpec& spec = args.spec;
  // Everything that can be checked without rendering is checked first, so
  // that a long render never ends in an error.
  std::error_code ec;
  if (leader) noteCreatedFolder(checkOutputFile(args.output), args.quiet);
  if (leader) checkRawOutput(spec.raw);
  if (leader && args.display) checkDisplayTransform(args.output, *args.display);
  const bool exr = std::filesystem::path(args.output).extension() == ".exr";
  // A preview's 8 bits mean sRGB; other spaces' numbers would show wrong colours.
  if (!exr && spec.colour.outputSpace != ColorSpaceId::Srgb)
    throw UsageError("--output-space", findOption("--output-space")->show(spec) + " needs an .exr output (" +
                                           args.output + " is a preview, whose colours are sRGB)");
  if ((args.checkpointSeconds > 0 || !args.resume.empty()) && !exr)
    throw UsageError("--checkpoint/--resume",
                     "need an .exr output (-o OUT.exr), the image that is continued");
  if (args.flo && !spec.aovs.flow) throw UsageError("--flo", "writes the flow AOV: add --aov flow");
  // The ID AOVs' id counts and flow's sums are not part of the running sums,
  // so a checkpoint could not continue them and ranks could not send them
  // back. (--tile and --crop parts are whole pixels: lensrt merge joins them.)
  if (const std::string unsaved = spec.aovs.unsavedAovs(); !unsaved.empty()) {
    if (args.checkpointSeconds > 0 || !args.resume.empty())
      throw UsageError("--aov",
                       unsaved +
                           " cannot be checkpointed or resumed (their sums are not in the running sums): "
                           "drop --checkpoint/--resume");
    if (shared)
      throw UsageError("--aov",
                       fmt::format("{} cannot be rendered across {} MPI ranks (their sums are not "
                                   "sent): run one rank, or split the frame with --tile and lensrt merge",
                                   unsaved, mpi.size()));
  }
  if (leader && !args.resume.empty() && !std::filesystem::exists(args.resume, ec))
    throw InputError(args.resume, "no such checkpoint");
  const std::string& envFile = spec.environment.file;
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
    if (!args.quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", spec.scene.file, message);
  };
  Warnings warnings([&](const std::string& message) {
    if (holding)
      held.push_back(message);
    else
      print(message);
  });

  // 2. Scene, lights, camera, render.
  PlanOptions planOptions;
  planOptions.scene = args.loaded;
  planOptions.quiet = args.quiet;
  // The flare light pass, once, for every image this process writes.
  planOptions.lightPass = leader;
  const RenderPlan plan(spec, warnings, planOptions);
  const RenderJob& job = plan.job();
  const Camera& camera = plan.camera();
  const RenderSettings& settings = plan.settings();
  const PixelRegion region = *settings.region;
  const ImageMetadata& identity = plan.identity();
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
    if (const auto failure = setUpTogether(mpi, spec.scene.file, identity)) {
      if (leader)
        fmt::print(stderr, "lensrt: error: rank {} of {}: {}\n", failure->rank, mpi.size(), failure->line);
      return failure->status;
    }
  }
  if (!leader) {
    const InterruptHandler interrupt;
    workForMain(mpi, camera, job.integrator(), settings, [&] { return interrupt.signal(); });
    return interrupt.signal() ? interrupt.exitStatus() : 0;
  }
  FilmState& state = *leaderState;

  // Passes, checkpoints and signals (the handlers only while rendering).
  const InterruptHandler interrupt;
  const auto started = std::chrono::steady_clock::now();
  auto lastCheckpoint = started;
  GatherCost gather;  // under MPI, once the render is done
  // The metadata of an image to write; with --noise on, the sensor reads it out first.
  const auto metadataOf = [&](RenderJobResult& r, Warnings& readoutWarnings) {
    ImageMetadata m = plan.finish(r, plan.shot(), args.commandLine, readoutWarnings);
    if (shared) m["lensrt:mpi_ranks"] = std::to_string(mpi.size());
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
      partial.output = renderOutput(camera, s, settings.flareLight.get());
      partial.seconds = std::chrono::duration<double>(now - started).count();
      // A checkpoint's readout says nothing: its clipped share changes from
      // one to the next as the noise settles, and the final image (written
      // on an interrupt too) gives the one warning.
      Warnings unsaid;
      const ImageMetadata metadata = metadataOf(partial, unsaid);
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
      finished = renderAcrossRanks(mpi, camera, job.integrator(), settings, state, control, &progress,
                                   rankSignal, &gather);
    }
    result.output = renderOutput(camera, state, settings.flareLight.get());
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  } else {
    result = job.renderPasses(camera, settings, state, control, args.quiet, finished);
  }

  // 3. Write: with the running sums when it can be continued.
  {
    ImageMetadata metadata = metadataOf(result, warnings);
    ImageWriteOptions options;
    options.display = args.display;
    if (args.display) {
      std::string shown = args.display->display.empty() ? "(default display)" : args.display->display;
      shown += " / ";
      shown += args.display->view.empty() ? "(default view)" : args.display->view;
      metadata["lensrt:ocio_display_view"] = shown;
    }
    if ((args.checkpointSeconds > 0 || !finished) && spec.aovs.unsavedAovs().empty())
      writeCheckpoint(args.output, state, result.output.image, metadata, options);
    else
      writeOutputImage(args.output, result.output.image, metadata, options);
    if (finished) plan.writeRaw(result.output.image);
    if (finished && !args.cameraJson.empty())
      writeTextFileAtomically(args.cameraJson, frameCameraJson(spec, camera, warnings).dump(2) + "\n");
    if (finished && args.flo)
      for (const char* direction : {"forward", "backward"}) {
        std::filesystem::path flo = args.output;
        flo.replace_extension(std::string(".") + direction + ".flo");
        const std::string channel = std::string("flow.") + direction;
        writeFlo(flo, result.output.image, channel + ".X", channel + ".Y");
      }
  }
  if (result.output.droppedSamples > 0 && !args.quiet)
    fmt::print(stderr, "lensrt: warning: {}: {} samples with NaN or infinite radiance were dropped\n",
               spec.scene.file, result.output.droppedSamples);
  if (!finished) {
    if (!args.quiet && !spec.aovs.unsavedAovs().empty())
      fmt::print(
          stderr,
          "lensrt: interrupted: wrote {} with {} of {} spp (not continuable: it has ID or flow AOVs)\n",
          args.output, state.samplesDone(), settings.samplesPerPixel);
    else if (!args.quiet)
      fmt::print(stderr, "lensrt: interrupted: wrote {} with {} of {} spp (continue with --resume {})\n",
                 args.output, state.samplesDone(), settings.samplesPerPixel, args.output);
    return interrupt.signal() ? interrupt.exitStatus() : 128 + rankSignal;
  }
  if (!args.quiet)
    fmt::print(stderr, "lensrt: wrote {} ({}x{}, {} spp, {:.2f} s, {})\n", args.output,
               result.output.image.width, result.output.image.height,
               adaptiveSppSummary(result.output.image).value_or(std::to_string(settings.samplesPerPixel)),
               result.seconds, camera.describe());
  return 0;
}

}  // namespace lensrt
