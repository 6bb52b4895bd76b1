#include "run/render_sequence.h"

#include <fmt/core.h>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>

#include "api/render_plan.h"
#include "api/scene_sequence.h"

namespace lensrt {

int renderSequence(const FileRender& job, const std::vector<SequenceFrame>& frames, MpiJob& mpi) {
  const bool leader = mpi.isMain();
  const bool quiet = job.quiet || !leader;
  // The file's warnings, each once for the whole sequence.
  Warnings warnings([&](const std::string& message) {
    if (!quiet) fmt::print(stderr, "lensrt: warning: {}: {}\n", job.spec.scene.file, message);
  });
  const SceneOptions options = sceneOptions(job.spec, quiet);
  SceneSequence sequence(SceneLoadOptions{options.scene, options.sceneIndex, options.limits, options.time},
                         warnings);
  if (mpi.size() > 1) {
    // Every rank has read the file: go on together, or stop together with the first error.
    if (const auto failure = mpi.agree(std::nullopt)) {
      if (leader)
        fmt::print(stderr, "lensrt: error: rank {} of {}: {}\n", failure->rank, mpi.size(), failure->line);
      return failure->status;
    }
  }
  // --focus auto focuses once, on what the focus pixel sees at the first
  // frame, and holds that distance: refocusing every frame would make the
  // field of view breathe as the subject moves. Keyframes rack it instead.
  // Every rank works it out alike, from the first frame of the range.
  FileRender held = job;
  std::shared_ptr<const Scene> firstScene;  // posed once, for the focus and the first frame
  if (job.spec.camera.autoFocus() && !frames.empty()) {
    RenderSpec first = job.spec;
    first.time.seconds = frames.front().seconds;
    first.time.frame.reset();
    firstScene = sequence.at(frames.front().seconds);
    const RenderPlan plan(first, warnings,
                          PlanOptions{.scene = firstScene, .repose = {}, .quiet = true, .lightPass = false});
    if (const double focus = plan.camera().info().focusMetres; focus > 0) {
      held.spec.camera.focusMetres = focus;
      held.spec.camera.focusPixel.reset();  // it chose the distance; a fixed focus takes none
    }
  }
  MpiJob alone;  // each frame is one process's render
  const auto ranks = static_cast<std::size_t>(mpi.size()), rank = static_cast<std::size_t>(mpi.rank());
  for (std::size_t i = rank; i < frames.size(); i += ranks) {
    FileRender frame = held;
    frame.quiet = quiet;
    frame.spec.time.seconds = frames[i].seconds;
    frame.spec.time.frame.reset();
    frame.output = frames[i].output;
    frame.cameraJson = std::filesystem::path(frame.output).replace_extension(".camera.json").string();
    frame.loaded = i == 0 && firstScene ? firstScene : sequence.at(frames[i].seconds);
    if (const int status = renderToFile(frame, alone); status != 0) return status;
    // The other ranks render quietly (one progress bar), but say what they wrote.
    if (!leader && !job.quiet)
      fmt::print(stderr, "lensrt: rank {} of {} wrote {}\n", mpi.rank(), mpi.size(), frame.output);
  }
  return 0;
}

}  // namespace lensrt
