#include "render/test_scene_util.h"

#include <cmath>

#include "render/lights.h"
#include "scene/render_scene.h"

namespace lensrt::test {

Mesh makeSphere(const Vec3f& centre, float radius, int rings, int segments, float thetaMax) {
  Mesh m;
  m.name = "sphere";
  const bool closed = thetaMax >= 3.14159f;
  // theta from the bottom pole (-Y) upward.
  for (int i = 0; i <= rings; ++i) {
    const float theta = thetaMax * float(i) / float(rings);
    for (int j = 0; j < segments; ++j) {
      const float phi = 2 * 3.14159265f * float(j) / float(segments);
      m.positions.push_back(
          centre +
          Vec3f{std::sin(theta) * std::cos(phi), -std::cos(theta), std::sin(theta) * std::sin(phi)} * radius);
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = i * segments + j, b = i * segments + (j + 1) % segments;
      const std::uint32_t c = (i + 1) * segments + j, d = (i + 1) * segments + (j + 1) % segments;
      // Outward-facing winding; skip the collapsed triangles at the poles.
      if (i > 0) m.indices.insert(m.indices.end(), {a, c, b});
      if (i + 1 < rings || !closed) m.indices.insert(m.indices.end(), {b, c, d});
    }
  return m;
}

Mesh makeQuadY(float height, float size) {
  Mesh m;
  m.name = "quad";
  const float h = size / 2;
  m.positions = {{-h, height, -h}, {h, height, -h}, {h, height, h}, {-h, height, h}};
  m.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from +Y
  return m;
}

Mesh makeRectFacingDown(float x0, float x1, float z0, float z1, float height) {
  Mesh m;
  m.name = "rect";
  m.positions = {{x0, height, z0}, {x1, height, z0}, {x1, height, z1}, {x0, height, z1}};
  m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from -Y
  return m;
}

Mesh makeBox(const Vec3f& lo, const Vec3f& hi) {
  Mesh m;
  m.name = "box";
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  // Two counter-clockwise triangles per face, seen from outside.
  m.indices = {0, 2, 1, 1, 2, 3,   // -z
               4, 5, 6, 5, 7, 6,   // +z
               0, 1, 4, 1, 5, 4,   // -y
               2, 6, 3, 3, 6, 7,   // +y
               0, 4, 2, 2, 4, 6,   // -x
               1, 3, 5, 3, 7, 5};  // +x
  return m;
}

Material whiteMatte(bool doubleSided) {
  Material m;
  m.name = "white";
  m.baseColor = {1, 1, 1, 1};
  m.metallic = 0;
  m.roughness = 1;
  m.doubleSided = doubleSided;
  return m;
}

Image renderTestScene(SceneDesc desc, const Camera& camera, const TestRenderSetup& setup,
                      std::uint64_t* dropped) {
  const RenderScene scene(std::move(desc));
  MaterialTable materials(scene.desc());
  if (setup.pureLambert) {
    materials.extra(-1).specularWeight = 0;
    for (int i = 0; i < int(scene.desc().materials.size()); ++i) materials.extra(i).specularWeight = 0;
  }
  const LightSet lights(materials, setup.environment, scene.bounds(), setup.lightSampling);
  const Integrator integrator(scene, materials, lights, setup.environment, setup.integrator);
  RenderOutput out = renderImage(camera, integrator, setup.render);
  if (dropped) *dropped = out.droppedSamples;
  return std::move(out.image);
}

double channelMean(const Image& image, const std::string& channel) {
  const int c = image.channelIndex(channel);
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / (double(image.width) * image.height);
}

}  // namespace lensrt::test
