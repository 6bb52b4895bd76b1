// `lensrt render`'s run, below its flag parsing: a render written to an image
// file (and a raw file), with everything that makes long renders safe:
// checks before any work, checkpoints and --resume, SIGINT/SIGTERM leaving a
// valid resumable image, and under MPI the ranks sharing the frame (rank 0
// alone reads, writes and speaks). The work itself is api's RenderJob.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "api/render_job.h"
#include "api/render_spec.h"
#include "image/preview_values.h"
#include "render/pixel_region.h"
#include "render/renderer.h"
#include "run/mpi_job.h"

namespace lensrt {

struct FileRender {
  RenderSpec spec;  // the scene, camera, sampling and outputs (--crop, --tile and --raw among them)
  // The scene already loaded and posed at the spec's time (a frame of
  // --frames); none: the render loads spec.scene.
  std::shared_ptr<const Scene> loaded;
  std::string output;  // -o: .exr (continuable) or a preview (.png, .jpg, .tif, ...), .dpx
  // --ocio-display/--ocio-view: the previews' OpenColorIO display transform.
  std::optional<DisplayTransform> display;
  double checkpointSeconds = 0;  // 0: no checkpoints
  std::string resume;            // a checkpoint to continue; empty: a new render
  bool quiet = false;            // no progress, warnings or summary on stderr
  // --flo on: also write --aov flow as Middlebury .flo files beside the
  // output, <stem>.forward.flo and <stem>.backward.flo (image/flo_io.h).
  bool flo = false;
  std::string commandLine;  // lensrt:command_line
  // A frame of --frames: where its camera's JSON goes (api/frame_camera.h),
  // written once the image is; empty: none.
  std::string cameraJson;
};

// Runs it; returns the exit status (0, or 128 + the signal that stopped it).
// Throws UsageError and InputError for bad settings and files, before any
// rendering wherever they can be found before it.
int renderToFile(const FileRender& job, MpiJob& mpi);

}  // namespace lensrt
