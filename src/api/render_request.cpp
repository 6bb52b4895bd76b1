#include "api/render_request.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

#include "api/film_colour.h"
#include "api/sensor_readout.h"
#include "core/error.h"
#include "render/film.h"

namespace lensrt {

void checkImageFitsInMemory(int width, int height, std::size_t channels) {
  // Two float copies of the image, and the running sums of every pixel.
  const double bytes = double(width) * double(height) *
                       (2.0 * double(channels) * sizeof(float) + PixelAccumulator::kStateBytes);
  const double physical = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  if (physical > 0 && bytes > physical)
    throw UsageError("--res", fmt::format("a {}x{} image with {} channels needs about {:.1f} GiB of memory, "
                                          "more than the {:.1f} GiB this machine has",
                                          width, height, channels, bytes / kGiB, physical / kGiB));
}

RenderResult render(const std::shared_ptr<const Scene>& scene, const RenderRequest& request,
                    Warnings& warnings, const RenderProgress& progress) {
  FrameOptions frame = request.frame;
  frame.quiet = false;  // the caller decides what to do with warnings
  // An animated scene moves over the time this frame records: posed again
  // over that span when it was loaded for another.
  std::shared_ptr<const Scene> posed = scene;
  if (const double span = recordedSpanSeconds(request.camera);
      !scene->geometry().desc().pose.empty() && scene->options().time.spanSeconds != span) {
    SceneLoadOptions options = scene->options();
    options.time.spanSeconds = span;
    posed = std::make_shared<const Scene>(options, warnings);
  }
  const RenderJob job(posed, frame, warnings);
  checkImageFitsInMemory(job.width(), job.height(), filmChannels(request.settings.aovs).size());
  const std::unique_ptr<Camera> camera = job.makeCamera(request.camera, warnings);
  const FilmColour colour = filmColour(request.camera, job.dominantLightColour(), warnings);
  const std::optional<SensorReadout> readout = sensorReadout(request.camera, camera->film(), colour.camera);
  checkRawOutput(request.raw);
  RenderSettings settings = request.settings;
  settings.filmResponse = colour.response;
  settings.timing = job.shutterTiming(request.camera, warnings);
  if (settings.samplesPerPixel < 1) throw UsageError("--spp", "expected at least 1 sample per pixel");
  const PixelRegion frameRegion = PixelRegion::wholeFrame(job.width(), job.height());
  const PixelRegion region = settings.region.value_or(frameRegion);
  if (!frameRegion.contains(region))
    throw UsageError("--crop", region.describe() + " is not inside the " + std::to_string(job.width()) + "x" +
                                   std::to_string(job.height()) + " image");
  settings.region = region;
  FilmState state(region, settings.aovs);
  // The command line's passes, so that the bits are its bits.
  PassControl control;
  if (progress)
    control.stopRequested = [&] { return !progress(state.samplesDone(), settings.samplesPerPixel); };
  bool finished = false;
  RenderJobResult done = job.renderPasses(*camera, settings, state, control, true, finished);
  if (progress && finished) progress(state.samplesDone(), settings.samplesPerPixel);

  RenderResult result;
  result.metadata = job.metadata(*camera, settings, done, request.commandLine);
  if (readout) readOut(*readout, done.output.image, result.metadata, settings.seed, warnings);
  if (!request.raw.file.empty() && finished)
    writeRawOutput(request.raw, done.output.image, readout, *camera, request.camera, colour.camera);
  result.metadata["lensrt:spp_requested"] = std::to_string(settings.samplesPerPixel);
  result.image = std::move(done.output.image);
  result.seconds = done.seconds;
  result.samplesPerPixel = state.samplesDone();
  result.finished = finished;
  result.droppedSamples = done.output.droppedSamples;
  result.camera = camera->describe();
  return result;
}

}  // namespace lensrt
