// A render job (api/render_job.h) shared by the ranks of an MPI job.
#pragma once

#include "api/render_job.h"
#include "run/mpi_job.h"

namespace lensrt {

// Rank 0 returns the image, the other ranks render the strips it sends
// (run/distributed_render.h) and return an empty result. Every rank calls
// it for the same camera; one rank is RenderJob::render.
RenderJobResult renderOnRanks(const RenderJob& job, const Camera& camera, const RenderSettings& settings,
                              bool quiet, const MpiJob& mpi);

}  // namespace lensrt
