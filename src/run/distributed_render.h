// A render shared by the ranks of an MPI job. Rank 0 holds the FilmState and
// runs the passes; in each pass it hands out horizontal strips of the region
// one at a time to whichever rank asks (its own render thread included),
// sending the strip's running sums with it and taking them back with the
// pass's samples added. A pixel's samples are still summed in sample order
// by one task, so the image has the bits of a render in one process, for
// any number of ranks and any order the strips come back in.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "camera/camera.h"
#include "run/mpi_job.h"
#include "image/image.h"
#include "render/film_state.h"
#include "render/integrator.h"
#include "render/progress.h"
#include "render/renderer.h"

namespace lensrt {

// Collective, called by every rank whose set-up (scene, camera) succeeded; a
// rank whose set-up failed calls mpi.agree with its failure instead.
// Waits for the others, then checks that every rank renders what rank 0
// renders (`identity`: scene files, camera, settings, seed), so that a node
// with another copy of the scene or the lens, or another working directory,
// fails the job instead of painting its strips from another render. Returns
// the lowest failing rank's failure, the same on every rank.
std::optional<MpiJob::Failure> setUpTogether(MpiJob& mpi, const std::string& scene,
                                              const ImageMetadata& identity);

// What sharing cost rank 0 (tools/bench-scaleout reports it): the time its
// main thread spent packing, sending, receiving and unpacking the other
// ranks' strips with their running sums, and the bytes that moved.
struct GatherCost {
  double seconds = 0;
  std::uint64_t bytes = 0;
};

// Rank 0: continues `state` to settings.samplesPerPixel like renderPasses,
// with every rank's help. Stops early (returning false) when `control` asks
// to or a rank reports a signal; `signal` then holds the first one reported
// (0 when none). Ends the other ranks' workForMain in both cases.
bool renderAcrossRanks(const MpiJob& mpi, const Camera& camera, const Integrator& integrator,
                       const RenderSettings& settings, FilmState& state, const PassControl& control,
                       Progress* progress, int& signal, GatherCost* cost = nullptr);

// The other ranks: render the strips rank 0 sends until it says the job is
// over. `signal()` (0: none) is reported to rank 0 with each strip.
void workForMain(const MpiJob& mpi, const Camera& camera, const Integrator& integrator,
                 const RenderSettings& settings, const std::function<int()>& signal);

}  // namespace lensrt
