// RenderJob::motionFlow: the moments --aov flow compares (render/motion_flow.h).
#include <fmt/core.h>

#include "api/render_job.h"
#include "core/error.h"
#include "scene/gltf_loader.h"

namespace lensrt {

std::shared_ptr<const MotionFlow> RenderJob::motionFlow(const Camera& camera, const CameraSpec& spec,
                                                        const ShutterSpec& shutter,
                                                        const std::optional<ShutterTiming>& timing,
                                                        double frameSeconds) const {
  auto flow = std::make_shared<MotionFlow>();
  const Transform& opening = camera.worldFromCamera();
  const auto cameraFromWorld = [](const Transform& worldFromCamera) {
    return worldFromCamera.invertible() ? worldFromCamera.inverse() : Transform();
  };
  if (frameSeconds > 0) {
    // The neighbouring frames: the scene posed at their shutters' opening,
    // as their own renders pose it (the frame's is the rendered scene's
    // first motion step). A camera node follows its animation; a pose the
    // caller gave, or a framed view of a camera-less scene, stays put.
    const SceneLoadOptions& options = scene_->options();
    Warnings quiet;  // the file's warnings were given when it was read
    GltfLoader loader(options.file, options.sceneIndex, quiet, options.limits);
    const auto neighbour = [&](double seconds) {
      FlowMoment m;
      AnimationTime at = options.time;
      at.seconds = seconds;
      at.spanSeconds = 0;
      // The geometry alone: an empty scene given as the previous one
      // hands over no materials, so no texture is decoded again.
      SceneDesc geometryOnly;
      auto posed = std::make_shared<SceneDesc>(loader.load(at, &geometryOnly));
      Transform pose = opening;
      if (!frame_.worldFromCamera && gltfCamera_.node >= 0)
        for (const CameraDesc& c : posed->cameras)
          if (c.node == gltfCamera_.node) pose = c.worldFromCamera;
      m.cameraFromWorld = cameraFromWorld(pose);
      m.scene = std::move(posed);
      // A keyed focus racks the film between frames (the image breathes);
      // the f-number moves no chief ray, so it needs no camera of its own.
      if (!spec.focusKeys.empty())
        m.camera =
            std::shared_ptr<const Camera>(makeCamera(spec, shutter, FlareSpec{}, seconds, quiet).camera);
      return m;
    };
    flow->now.cameraFromWorld = cameraFromWorld(opening);
    flow->next = neighbour(options.time.seconds + frameSeconds);
    flow->previous = neighbour(options.time.seconds - frameSeconds);
    return flow;
  }
  // A still frame: the motion over the shutter (its span: with a rolling
  // shutter, to the last row's closing), forward from the opening to the
  // closing and backward from the closing to the opening.
  if (scene_->geometry().desc().motionSteps == 0 || !timing)
    throw UsageError(
        "--aov", fmt::format("flow needs motion: nothing in {} moves over the shutter (give --shutter "
                             "SECONDS on an animated scene, or --flow-step SECONDS, --frame N or --frames "
                             "A:B for the motion to the neighbouring frames)",
                             scene_->options().file));
  flow->overShutter = true;
  flow->now.cameraFromWorld = cameraFromWorld(opening);
  flow->next.spanEnd = true;
  flow->next.cameraFromWorld =
      cameraFromWorld(timing->cameraSteps.empty() ? opening : timing->cameraSteps.back() * opening);
  return flow;
}

}  // namespace lensrt
