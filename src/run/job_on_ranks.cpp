#include "run/job_on_ranks.h"

#include <chrono>

#include "run/distributed_render.h"
#include "render/flare_light_pass.h"
#include "render/progress.h"

namespace lensrt {

RenderJobResult renderOnRanks(const RenderJob& job, const Camera& camera, const RenderSettings& settings,
                              bool quiet, const MpiJob& mpi) {
  if (mpi.size() == 1) return job.render(camera, settings, quiet);
  if (!mpi.isMain()) {
    workForMain(mpi, camera, job.integrator(), settings, [] { return 0; });
    return {};
  }
  const auto start = std::chrono::steady_clock::now();
  const FilmGeometry& film = camera.film();
  FilmState state(settings.region.value_or(PixelRegion::wholeFrame(film.width, film.height)), settings.aovs);
  {
    Progress progress(state.region().pixelCount() * std::uint64_t(settings.samplesPerPixel),
                      Progress::styleFor(stderr, quiet));
    int signal = 0;
    renderAcrossRanks(mpi, camera, job.integrator(), settings, state, PassControl{}, &progress, signal);
  }
  RenderJobResult result;
  result.output = renderOutput(camera, state, settings.flareLight.get());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lensrt
