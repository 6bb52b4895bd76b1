// Scenes built in code for the renderer's tests: meshes with known geometry
// and a one-call render through the whole pipeline.
#pragma once

#include <functional>

#include "camera/camera.h"
#include "image/image.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"

namespace lensrt::test {

// Latitude-longitude sphere around `centre`, flat-shaded (no vertex normals), so
// the polyhedron is exactly convex. thetaMax < pi leaves a bowl: the part of the
// sphere with polar angle (from -Y, downward) below thetaMax.
Mesh makeSphere(const Vec3f& centre, float radius, int rings, int segments, float thetaMax = 3.14159265f);
// Square in the plane y = height, side `size`, centred on the Y axis, facing +Y.
Mesh makeQuadY(float height, float size);
// Rectangle [x0,x1] x [z0,z1] at y = height, facing -Y (downward).
Mesh makeRectFacingDown(float x0, float x1, float z0, float z1, float height);

// Axis-aligned box [lo, hi], outward-facing winding.
Mesh makeBox(const Vec3f& lo, const Vec3f& hi);

// A material that is a pure Lambertian reflector once its specular weight is
// zeroed (see renderTestScene's `pureLambert`).
Material whiteMatte(bool doubleSided = false);

struct TestRenderSetup {
  Environment environment;
  IntegratorSettings integrator;
  RenderSettings render;
  // Materials whose specular layer is removed: an exactly Lambertian BRDF.
  bool pureLambert = true;
  LightSampling lightSampling = LightSampling::Tree;
};

Image renderTestScene(SceneDesc scene, const Camera& camera, const TestRenderSetup& setup,
                      std::uint64_t* dropped = nullptr);

// Mean of one channel over the whole image, or over pixels where `mask` > 0.5.
double channelMean(const Image& image, const std::string& channel);

}  // namespace lensrt::test
