// `lensrt render`'s run, below its flag parsing: a render written to an image
// file (and a raw file), with everything that makes long renders safe:
// checks before any work, checkpoints and --resume, SIGINT/SIGTERM leaving a
// valid resumable image, and under MPI the ranks sharing the frame (rank 0
// alone reads, writes and speaks). The work itself is api's RenderJob.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "api/camera_options.h"
#include "api/raw_output.h"
#include "api/render_job.h"
#include "cluster/cluster.h"
#include "image/preview_values.h"
#include "render/pixel_region.h"
#include "render/renderer.h"

namespace lensrt {

struct FileRender {
  SceneOptions scene;  // the scene file and the frame
  // The scene already loaded and posed at scene.time (a frame of --frames);
  // none: render loads scene.scene.
  std::shared_ptr<const Scene> loaded;
  CameraOptions camera;     // the model and its optics, and the sensor
  RenderSettings settings;  // spp, seed, threads, tile size, AOVs; the region comes from tile/crop
  std::string output;       // -o: .exr (continuable) or a preview (.png, .jpg, .tif, ...), .dpx
  // --ocio-display/--ocio-view: the previews' OpenColorIO display transform.
  std::optional<DisplayTransform> display;
  RawOutputOptions raw;  // --raw and --cfa
  // --tile I/N (strips top to bottom) or --crop X0,X1,Y0,Y1: the part of the frame.
  struct Strip {
    int index = 0, count = 1;
  };
  std::optional<Strip> tile;
  std::optional<PixelRegion> crop;
  double checkpointSeconds = 0;  // 0: no checkpoints
  std::string resume;            // a checkpoint to continue; empty: a new render
  bool quiet = false;            // no progress, warnings or summary on stderr
  std::string commandLine;       // lensrt:command_line
};

// Runs it; returns the exit status (0, or 128 + the signal that stopped it).
// Throws UsageError and InputError for bad settings and files, before any
// rendering wherever they can be found before it.
int renderToFile(const FileRender& job, Cluster& cluster);

}  // namespace lensrt
