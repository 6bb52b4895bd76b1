#include "scene/scene_desc.h"

#include <algorithm>
#include <cmath>

namespace lensrt {

// The extension's matrices: T = [1 0 ox; 0 1 oy], R = [cos sin; -sin cos],
// S = diag(sx, sy); uv' = T * R * S * uv (scale first, then rotate, then offset).
UvTransform UvTransform::fromOffsetRotationScale(Vec2f offset, float rotation, Vec2f scale) {
  const float c = std::cos(rotation), s = std::sin(rotation);
  UvTransform t;
  t.m[0] = c * scale.x;
  t.m[1] = s * scale.y;
  t.m[2] = offset.x;
  t.m[3] = -s * scale.x;
  t.m[4] = c * scale.y;
  t.m[5] = offset.y;
  return t;
}

Bounds3f SceneDesc::worldBounds() const {
  std::vector<Bounds3f> meshBounds(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i)
    for (const Vec3f& p : meshes[i].positions) meshBounds[i].extend(p);
  Bounds3f b;
  for (const MeshInstance& inst : instances) b.extend(inst.worldFromObject(meshBounds[inst.mesh]));
  return b;
}

}  // namespace lensrt

namespace lensrt {

Vec3f Material::attenuationCoefficient() const {
  if (!(attenuationDistance > 0) || !std::isfinite(attenuationDistance)) return {0, 0, 0};
  const auto sigma = [&](float c) { return -std::log(std::clamp(c, 1e-6f, 1.0f)) / attenuationDistance; };
  return {sigma(attenuationColor.x), sigma(attenuationColor.y), sigma(attenuationColor.z)};
}

float Material::iorAt(float nm) const {
  if (!(dispersion > 0)) return ior;
  const float abbe = 20.0f / dispersion;
  return std::max(1.0f, ior + (ior - 1) / abbe * (523655.0f / (nm * nm) - 1.5168f));
}

}  // namespace lensrt
