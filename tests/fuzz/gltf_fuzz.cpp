// libFuzzer target for the glTF front end: the input is written to a file
// (.glb when it starts with the binary magic, else .gltf) and goes through
// tinygltf, our conversion (loadGltf), camera selection and the Embree scene,
// then a few rays, each hit's material and its BSDF. Only InputError may escape; a crash, a sanitizer report,
// any other exception or a non-finite hit is a finding.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/warnings.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/oiio_plugin_first.h"
#include "render/gltf_bsdf.h"
#include "render/material_eval.h"
#include "scene/camera_selection.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"
#include "scene/texture_sampling.h"

namespace {

using namespace lensrt;

// One directory per process, so parallel fuzz jobs do not share files;
// relative URIs in the input resolve (and fail) inside it.
const std::filesystem::path& workDir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("lensrt_fuzz_gltf_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// Every texture slot of the hit's material, read the way the renderer reads it
// (UV set, KHR_texture_transform, sampler), must give finite texels.
void checkTextures(const SceneDesc& desc, const SurfaceHit& hit) {
  if (hit.material < 0 || static_cast<std::size_t>(hit.material) >= desc.materials.size()) return;
  const Material& m = desc.materials[static_cast<std::size_t>(hit.material)];
  for (const TextureRef* ref : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                                &m.emissiveTexture, &m.specularTexture, &m.specularColorTexture,
                                &m.transmissionTexture, &m.clearcoatTexture, &m.clearcoatRoughnessTexture,
                                &m.clearcoatNormalTexture, &m.sheenColorTexture, &m.sheenRoughnessTexture}) {
    if (!ref->valid()) continue;
    LENSRT_FUZZ_CHECK(static_cast<std::size_t>(ref->texture) < desc.textures.size());
    const Vec4f t =
        sampleTexture(desc.textures[static_cast<std::size_t>(ref->texture)], ref->uv(hit.uv, hit.uv1));
    LENSRT_FUZZ_CHECK(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w));
  }
}

// The material at the hit as the renderer builds it (textures, normal maps,
// the layer extensions' factors) and its BSDF: samples and values finite.
void checkShading(const MaterialTable& materials, const SurfaceHit& hit, const Vec3f& wo) {
  const ShadingPoint sp = evaluateMaterial(materials, hit, wo);
  LENSRT_FUZZ_CHECK(isFinite(sp.frame.n) && isFinite(sp.coatFrame.n) && isFinite(sp.emission));
  const GltfBsdf bsdf(sp.bsdf, sp.frame, sp.coatFrame);
  for (int k = 0; k < 8; ++k) {
    const float u = (k + 0.5f) / 8;
    const std::optional<BsdfSample> s = bsdf.sample(wo, u, {u, 1 - u});
    if (!s) continue;
    LENSRT_FUZZ_CHECK(isFinite(s->wi) && isFinite(s->f) && std::isfinite(s->pdf) && s->pdf > 0);
    LENSRT_FUZZ_CHECK(isFinite(bsdf.eval(wo, s->wi)) && std::isfinite(bsdf.pdf(wo, s->wi)));
  }
}

void checkHit(const RenderScene& scene, const MaterialTable& materials, const Ray& ray,
              const std::optional<SurfaceHit>& hit) {
  if (!hit) return;
  checkTextures(scene.desc(), *hit);
  checkShading(materials, *hit, -ray.direction);
  LENSRT_FUZZ_CHECK(std::isfinite(hit->t) && isFinite(hit->position));
  LENSRT_FUZZ_CHECK(isFinite(hit->geometricNormal) && isFinite(hit->shadingNormal));
  LENSRT_FUZZ_CHECK(std::abs(length(hit->shadingNormal) - 1.0f) < 1e-3f);
  // COLOR_0 is clamped to [0, 1] on loading; interpolation keeps it there.
  for (const float c : {hit->color.x, hit->color.y, hit->color.z, hit->color.w})
    LENSRT_FUZZ_CHECK(c >= 0.0f && c <= 1.0f + 1e-5f);
}

void exercise(const std::filesystem::path& file) {
  Warnings warnings;
  // Confined to workDir() as every scene is by default: a URI naming
  // /etc/passwd, /dev/zero or a FIFO is refused, never read. The texture
  // budget stays well inside libFuzzer's 2 GB memory limit.
  SceneReadLimits limits;
  limits.maxTextureBytes = std::uint64_t{512} << 20;
  // Posed over a span: an animated file also goes through the motion
  // steps (scene_motion.h) and Embree's motion-blur meshes.
  SceneDesc desc = loadGltf(file, -1, warnings, limits, AnimationTime{0.0, "", 0.5});
  const CameraDesc camera = selectCamera(desc, "", 1.5f);
  LENSRT_FUZZ_CHECK(isFinite(camera.worldFromCamera.point(Vec3f{0, 0, 0})));
  const RenderScene scene(std::move(desc));
  const MaterialTable materials(scene.desc());
  const Bounds3f b = scene.bounds();
  const Vec3f eye = camera.worldFromCamera.point(Vec3f{0, 0, 0});
  for (int i = 0; i < 16; ++i) {
    // Through the bounds' corners and centre from the camera, and along the axes.
    const Vec3f corner{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
    const Vec3f target = i < 8 ? corner : b.center();
    const Vec3f d = target - eye;
    if (length(d) > 0.0f && isFinite(d)) {
      const Ray ray{eye, normalize(d), 0.0f, kInfinityF, (i & 1) ? 0.5f : 0.0f};
      checkHit(scene, materials, ray, scene.intersect(ray));
    }
    const Vec3f axis{i % 3 == 0 ? 1.f : 0.f, i % 3 == 1 ? 1.f : 0.f, i % 3 == 2 ? 1.f : 0.f};
    const Vec3f from = b.center() - axis * (length(b.diagonal()) + 1.0f);
    if (isFinite(from)) {
      const Ray ray{from, axis};
      checkHit(scene, materials, ray, scene.intersect(ray));
      scene.occluded(Ray{from, axis, 0.0f, 1.0f});
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  lensrt::fuzz::loadOiioPluginFirst();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  const std::filesystem::path file = workDir() / (glb ? "input.glb" : "input.gltf");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    exercise(file);
  } catch (const InputError&) {
    // Rejected with a message: the expected outcome for most inputs.
  }
  return 0;
}
