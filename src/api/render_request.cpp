#include "api/render_request.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

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
  PlanOptions options;
  options.scene = scene;
  options.repose = request.repose;
  checkRawOutput(request.spec.raw);
  const RenderPlan plan(request.spec, warnings, options);
  const RenderSettings& settings = plan.settings();
  FilmState state(*settings.region, settings.aovs);
  // The command line's passes, so that the bits are its bits.
  PassControl control;
  if (progress)
    control.stopRequested = [&] { return !progress(state.samplesDone(), settings.samplesPerPixel); };
  bool finished = false;
  RenderJobResult done = plan.job().renderPasses(plan.camera(), settings, state, control, true, finished);
  if (progress && finished) progress(state.samplesDone(), settings.samplesPerPixel);

  RenderResult result;
  result.metadata = plan.finish(done, plan.shot(), request.commandLine, warnings);
  if (finished) plan.writeRaw(done.output.image);
  result.image = std::move(done.output.image);
  result.seconds = done.seconds;
  result.samplesPerPixel = state.samplesDone();
  result.finished = finished;
  result.droppedSamples = done.output.droppedSamples;
  result.camera = plan.camera().describe();
  return result;
}

}  // namespace lensrt
