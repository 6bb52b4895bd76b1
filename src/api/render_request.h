// One render of a loaded scene, as a library call: RenderRequest ->
// RenderResult. Python's Scene.render is this function; `lensrt render` runs
// the same RenderJob steps with its checkpoints, MPI ranks and progress bar.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "api/render_plan.h"
#include "api/render_spec.h"
#include "api/scene.h"
#include "core/warnings.h"
#include "image/image.h"
#include "render/renderer.h"

namespace lensrt {

struct RenderRequest {
  RenderSpec spec;  // the scene's frame, camera, sampling, outputs (its scene file and time: the Scene's)
  // lensrt:command_line in the metadata: how the render was asked for.
  std::string commandLine;
  ScenePoser repose;  // poses the scene over another span; none: reads the file again
};

// Called on the calling thread between passes (which double in length from
// 1 spp, up to about a second each): samples per pixel done and asked for.
// Returning false stops the render there, with whole passes.
using RenderProgress = std::function<bool(int samplesDone, int samplesTotal)>;

struct RenderResult {
  Image image;             // R, G, B, A, then the AOVs' channels
  ImageMetadata metadata;  // what `lensrt render` writes in the EXR header
  double seconds = 0.0;
  int samplesPerPixel = 0;  // done: fewer than asked when stopped
  bool finished = true;
  std::uint64_t droppedSamples = 0;  // NaN / infinite radiance
  std::string camera;                // Camera::describe()
};

// The image is held in memory as floats (and copied once more to write it)
// beside the pixels' running sums: a resolution this machine cannot hold is a
// usage error ("--res"), not a crash mid-render.
void checkImageFitsInMemory(int width, int height, std::size_t channels);

// Plans the render (api/render_plan.h; warnings go to `warnings`), then renders.
// Throws UsageError for bad options, InputError for bad files.
RenderResult render(const std::shared_ptr<const Scene>& scene, const RenderRequest& request,
                    Warnings& warnings, const RenderProgress& progress = {});

}  // namespace lensrt
