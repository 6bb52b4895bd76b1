#include "render/motion_flow.h"

#include <cmath>

#include "optics/glass.h"

namespace lensrt {

std::optional<Vec3d> surfacePointAt(const SceneDesc& scene, bool spanEnd, int instance,
                                    std::uint32_t primitive, const Vec2f& barycentric) {
  if (instance < 0 || std::size_t(instance) >= scene.instances.size()) return std::nullopt;
  const MeshInstance& inst = scene.instances[std::size_t(instance)];
  // The motion's steps hold a deformed mesh each; a still instance has none.
  const bool moved = spanEnd && inst.moves();
  const int meshIndex = moved ? inst.motion.back().mesh : inst.mesh;
  const Transform& worldFromObject = moved ? inst.motion.back().worldFromObject : inst.worldFromObject;
  if (meshIndex < 0 || std::size_t(meshIndex) >= scene.meshes.size()) return std::nullopt;
  const Mesh& mesh = scene.meshes[std::size_t(meshIndex)];
  if (std::size_t(primitive) >= mesh.triangleCount()) return std::nullopt;
  const std::uint32_t* idx = &mesh.indices[3 * std::size_t(primitive)];
  const double u = barycentric.x, v = barycentric.y, w = 1.0 - u - v;
  // Barycentrics interpolate the triangle's corners in object space; the
  // placement is affine, so world space gives the same point.
  const Vec3d p = Vec3d(mesh.positions[idx[0]]) * w + Vec3d(mesh.positions[idx[1]]) * u +
                  Vec3d(mesh.positions[idx[2]]) * v;
  return worldFromObject.point(p);
}

namespace {

// The surface point in the camera's frame at a moment (metres).
std::optional<Vec3d> cameraPointAt(const FlowMoment& m, const SceneDesc& rendered, int instance,
                                   std::uint32_t primitive, const Vec2f& barycentric) {
  const SceneDesc& scene = m.scene ? *m.scene : rendered;
  // Another pose of the file lists the same instances in the same order;
  // one placed by another node is not this object.
  if (m.scene &&
      (instance < 0 || std::size_t(instance) >= scene.instances.size() ||
       std::size_t(instance) >= rendered.instances.size() ||
       scene.instances[std::size_t(instance)].node != rendered.instances[std::size_t(instance)].node))
    return std::nullopt;
  const std::optional<Vec3d> p = surfacePointAt(scene, m.spanEnd, instance, primitive, barycentric);
  if (!p) return std::nullopt;
  return m.cameraFromWorld.point(*p);
}

std::optional<Vec2d> imageOf(const Camera& camera, const Vec3d& point, ChiefRayHint& hint) {
  // The wavelength Lens.project takes by default (the d line).
  const ProjectedPoint q = camera.projectCameraPointHinted(point, kWavelengthDNm, &hint);
  if (!std::isfinite(q.raster.x) || !std::isfinite(q.raster.y)) return std::nullopt;
  return q.raster;
}

}  // namespace

SampleFlow sampleFlow(const MotionFlow& flow, const SceneDesc& rendered, const Camera& camera, int instance,
                      std::uint32_t primitive, const Vec2f& barycentric, FlowHints& hints) {
  const std::optional<Vec3d> here = cameraPointAt(flow.now, rendered, instance, primitive, barycentric);
  if (!here) return {};
  const std::optional<Vec2d> now = imageOf(camera, *here, hints.now);
  if (!now) return {};
  const auto at = [&](const FlowMoment& m, ChiefRayHint& hint) -> std::optional<Vec2d> {
    const std::optional<Vec3d> there = cameraPointAt(m, rendered, instance, primitive, barycentric);
    if (!there) return std::nullopt;
    // Still against the same camera: the same image, so no motion, exactly
    // (a solve from another start could differ in its last bits).
    if (*there == *here && !m.camera) return now;
    // The pixel's first sample at another moment starts where it did now
    // (the object-side chief ray does not depend on where the film is).
    if (!hint.valid()) hint = hints.now;
    return imageOf(m.camera ? *m.camera : camera, *there, hint);
  };
  SampleFlow f;
  if (const std::optional<Vec2d> next = at(flow.next, hints.next)) f.forward = *next - *now;
  if (flow.overShutter) {
    if (f.forward) f.backward = *f.forward * -1.0;
  } else if (const std::optional<Vec2d> previous = at(flow.previous, hints.previous)) {
    f.backward = *previous - *now;
  }
  return f;
}

void FlowSums::add(const SampleFlow& f, int hitInstance) {
  if (taken == 0)
    instance = hitInstance;
  else if (hitInstance != instance)
    mixed = true;
  ++taken;
  if (f.forward) {
    forward[0] += f.forward->x;
    forward[1] += f.forward->y;
    ++forwardCount;
  }
  if (f.backward) {
    backward[0] += f.backward->x;
    backward[1] += f.backward->y;
    ++backwardCount;
  }
}

void FlowSums::write(float* out) const {
  out[0] = forwardCount ? float(forward[0] / forwardCount) : 0.0f;
  out[1] = forwardCount ? float(forward[1] / forwardCount) : 0.0f;
  out[2] = backwardCount ? float(backward[0] / backwardCount) : 0.0f;
  out[3] = backwardCount ? float(backward[1] / backwardCount) : 0.0f;
}

}  // namespace lensrt
