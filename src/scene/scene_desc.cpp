#include "scene/scene_desc.h"

namespace lensrt {

Bounds3f SceneDesc::worldBounds() const {
  std::vector<Bounds3f> meshBounds(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i)
    for (const Vec3f& p : meshes[i].positions) meshBounds[i].extend(p);
  Bounds3f b;
  for (const MeshInstance& inst : instances) b.extend(inst.worldFromObject(meshBounds[inst.mesh]));
  return b;
}

}  // namespace lensrt
