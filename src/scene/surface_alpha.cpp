#include "scene/surface_alpha.h"

#include <algorithm>

#include "scene/texture_sampling.h"

namespace lensrt {

float surfaceAlpha(const SceneDesc& scene, const Mesh& mesh, const Material& material, unsigned prim, float u,
                   float v) {
  float alpha = material.baseColor.w;
  const std::uint32_t* idx = &mesh.indices[3 * static_cast<std::size_t>(prim)];
  const float w = 1 - u - v;
  const TextureRef& ref = material.baseColorTexture;
  if (ref.valid() && static_cast<std::size_t>(ref.texture) < scene.textures.size()) {
    const auto interp = [&](const std::vector<Vec2f>& a) {
      return a.empty() ? Vec2f{0, 0} : a[idx[0]] * w + a[idx[1]] * u + a[idx[2]] * v;
    };
    alpha *= sampleTexture(scene.textures[ref.texture], ref.uv(interp(mesh.uvs), interp(mesh.uvs1))).w;
  }
  if (!mesh.colors.empty())
    alpha *= std::clamp(mesh.colors[idx[0]].w * w + mesh.colors[idx[1]].w * u + mesh.colors[idx[2]].w * v,
                        0.0f, 1.0f);
  return alpha;
}

float surfaceCoverage(const SceneDesc& scene, const Mesh& mesh, const Material& material, unsigned prim,
                      float u, float v) {
  switch (material.alphaMode) {
    case AlphaMode::Opaque:
      return 1.0f;
    case AlphaMode::Mask:
      return surfaceAlpha(scene, mesh, material, prim, u, v) >= material.alphaCutoff ? 1.0f : 0.0f;
    case AlphaMode::Blend:
      return std::clamp(surfaceAlpha(scene, mesh, material, prim, u, v), 0.0f, 1.0f);
  }
  return 1.0f;
}

}  // namespace lensrt
