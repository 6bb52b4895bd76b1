// Optical flow (--aov flow): where the surface point a camera sample sees
// first images at two moments, through the camera's own projection
// (camera/projection.h), so the motion carries the lens's distortion.
// Each sample adds its image's displacement; a pixel writes the mean over
// its samples that hit. Design notes: docs/ground-truth.md ("Flow").
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "camera/camera.h"
#include "core/transform.h"
#include "core/vec.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The scene and the camera at one moment.
struct FlowMoment {
  // The scene posed at that moment; none: the rendered scene.
  std::shared_ptr<const SceneDesc> scene;
  // Where in that scene's motion: its last step (the end of the recorded
  // span, the shutter's closing) rather than its first (the opening).
  bool spanEnd = false;
  Transform cameraFromWorld;  // the camera's pose at that moment
  // The camera at that moment when its projection differs from the
  // rendered one's (a keyframed focus); none: the rendered camera.
  std::shared_ptr<const Camera> camera;
};

// Forward: a point's image at `next` minus its image `now`. Backward: its
// image at `previous` minus that `now`; over a still frame's shutter (`now`
// its opening, `next` its closing) from the closing back to the opening,
// minus forward. Each point is projected once per moment.
struct MotionFlow {
  FlowMoment now, next, previous;
  bool overShutter = false;  // backward is minus forward; `previous` unused
};

// The world position, in a scene at a moment, of the point of instance
// `instance`'s triangle `primitive` at barycentrics (u, v) (Embree's: the
// weights of its second and third vertex). None when that scene has no such
// instance or triangle (the poses differ in what they contain).
std::optional<Vec3d> surfacePointAt(const SceneDesc& scene, bool spanEnd, int instance,
                                    std::uint32_t primitive, const Vec2f& barycentric);

// One sample's forward and backward image motion in raster pixels (x right,
// y down); a direction is none when the point has no image at one of its
// moments (behind the camera, or no chief ray through the lens).
struct SampleFlow {
  std::optional<Vec2d> forward, backward;
};
// Where the full lens's chief-ray solves of a pixel's samples start: at
// each moment, the pixel's last sample's solve there.
struct FlowHints {
  ChiefRayHint now, next, previous;
};
SampleFlow sampleFlow(const MotionFlow& flow, const SceneDesc& rendered, const Camera& camera, int instance,
                      std::uint32_t primitive, const Vec2f& barycentric, FlowHints& hints);

// The samples that hit whose motion a pixel's flow averages: its first
// ones (in sample order, so the same whatever the threads, tiles or passes).
// Each costs three projections, and through the full lens a projection is
// a chief-ray solve (~0.5 us), more than a path of a simple scene: past a few
// samples the flow of a pixel changes little (only where it mixes surfaces),
// while its cost would grow with the spp. So: its first kFlowSamplesPerPixel,
// or its first kFlowSamplesOneObject when those all hit one object (one
// instance): their motions then differ only by where on it they land.
inline constexpr std::uint32_t kFlowSamplesPerPixel = 8;
inline constexpr std::uint32_t kFlowSamplesOneObject = 4;

// A pixel's running flow sums: each direction's displacement summed over
// the samples that have one, and their count.
struct FlowSums {
  double forward[2] = {0, 0}, backward[2] = {0, 0};
  // From the pixel's own samples in order: the same bits whatever the schedule.
  FlowHints hints;
  std::int32_t instance = -1;  // the first sample's
  // Counts up to kFlowSamplesPerPixel.
  std::uint8_t forwardCount = 0, backwardCount = 0;
  std::uint8_t taken = 0;  // samples added, with an image or not
  bool mixed = false;      // they hit more than one instance
  // Whether the pixel has its samples (see above): later ones are not projected.
  bool full() const { return taken >= kFlowSamplesPerPixel || (taken >= kFlowSamplesOneObject && !mixed); }
  // A sample of the instance `hitInstance`.
  void add(const SampleFlow& f, int hitInstance);
  // flow.forward.X, .Y, flow.backward.X, .Y: the means, 0 without samples.
  void write(float* out) const;
};

}  // namespace lensrt
