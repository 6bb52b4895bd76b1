#include "render/light_level.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/constants.h"
#include "optics/lens_system.h"  // refract
#include "render/lights.h"

namespace lensrt {
namespace {

struct EmissiveTriangle {
  Vec3f centroid;
  Vec3f normal;     // unit, the front
  double power;     // L * area, W/sr of luminance along the normal
  double radiance;  // L, for the pi L bound
  bool doubleSided;
};

// Radiance of an emissive triangle, averaged over four interior points.
double meanEmittedLuminance(const MaterialTable& materials, const Mesh& mesh, std::size_t t) {
  constexpr float kBary[4][2] = {{1 / 3.0f, 1 / 3.0f}, {0.6f, 0.2f}, {0.2f, 0.6f}, {0.2f, 0.2f}};
  const std::uint32_t i[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
  const auto at = [&](const std::vector<Vec2f>& uvs, float b1, float b2) {
    if (uvs.empty()) return Vec2f{0, 0};
    return uvs[i[0]] * (1 - b1 - b2) + uvs[i[1]] * b1 + uvs[i[2]] * b2;
  };
  double sum = 0;
  for (const auto& b : kBary)
    sum += luminance(
        emittedRadiance(materials, mesh.material, at(mesh.uvs, b[0], b[1]), at(mesh.uvs1, b[0], b[1]), 1.0f));
  return sum / 4;
}

std::vector<EmissiveTriangle> emissiveTriangles(const MaterialTable& materials) {
  const SceneDesc& scene = materials.scene();
  std::vector<EmissiveTriangle> out;
  for (const MeshInstance& inst : scene.instances) {
    if (inst.mesh < 0 || std::size_t(inst.mesh) >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[inst.mesh];
    const Material& m = materials.material(mesh.material);
    if (!m.isEmissive()) continue;
    const float handed = inst.worldFromObject.determinant3x3() < 0 ? -1.0f : 1.0f;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const Vec3f p0 = inst.worldFromObject.point(mesh.positions[mesh.indices[3 * t]]);
      const Vec3f p1 = inst.worldFromObject.point(mesh.positions[mesh.indices[3 * t + 1]]);
      const Vec3f p2 = inst.worldFromObject.point(mesh.positions[mesh.indices[3 * t + 2]]);
      const Vec3f c = cross(p1 - p0, p2 - p0);
      const float len = length(c);
      const double radiance = meanEmittedLuminance(materials, mesh, t);
      if (!(len > 0) || !std::isfinite(len) || !(radiance > 0)) continue;
      out.push_back(
          {(p0 + p1 + p2) / 3.0f, c * (handed / len), radiance * 0.5 * len, radiance, m.doubleSided});
    }
  }
  return out;
}

// The surface a probe ray sees, as a camera path sees it: past transmitting
// surfaces (glass, water: glTF's KHR_materials_transmission), straight
// through a thin-walled sheet and refracted (Snell, at the material's index)
// into and out of a volume, reflected where the refraction is total. The
// ray that reaches the surface goes with it; nullopt when the ray leaves the
// scene, or after many crossings.
struct SeenSurface {
  SurfaceHit hit;
  Ray ray;
};
std::optional<SeenSurface> seenSurface(const RenderScene& scene, const MaterialTable& materials, Ray ray) {
  constexpr int kMaxCrossings = 16;
  for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
    const std::optional<SurfaceHit> hit = scene.intersect(ray);
    if (!hit) return std::nullopt;
    const ShadingPoint sp = evaluateMaterial(materials, *hit, -ray.direction);
    if (!((1 - sp.bsdf.base.metallic) * sp.bsdf.transmission > 0)) return SeenSurface{*hit, ray};
    const Material& m = materials.material(hit->material);
    const Vec3f n = sp.geometricNormal;  // facing the ray's origin
    Vec3d out = Vec3d(ray.direction);
    if (!m.thinWalled()) {
      // Entering through the winding's front, leaving through its back.
      const double ior = std::max(1.0f, m.ior), inside = sp.frontFace ? ior : 1.0,
                   outside = sp.frontFace ? 1.0 : ior;
      if (!refract(Vec3d(ray.direction), Vec3d(n), outside, inside, out))
        out = Vec3d(ray.direction - n * (2 * dot(ray.direction, n)));
    }
    const Vec3f d = normalize(Vec3f(out));
    // Offset to the side the ray goes on to, as camera paths do.
    const float scale = 2e-4f * std::max({1.0f, std::abs(hit->position.x), std::abs(hit->position.y),
                                          std::abs(hit->position.z)});
    ray.origin = hit->position + (dot(d, n) > 0 ? n : -n) * scale;
    ray.direction = d;
    ray.tMax = kInfinityF;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> medianEmitterIrradiance(const RenderScene& scene, const MaterialTable& materials,
                                              std::span<const Ray> probes) {
  const SceneDesc& desc = materials.scene();
  const std::vector<EmissiveTriangle> triangles = emissiveTriangles(materials);
  // Bounded work on meshes with very many emissive triangles: every k-th
  // triangle, weighted by k (deterministic, and a fair estimate of a sum).
  constexpr std::size_t kMaxPairs = std::size_t(1) << 22;
  const std::size_t stride = std::max<std::size_t>(1, triangles.size() * probes.size() / kMaxPairs);
  std::vector<double> levels;
  for (const Ray& probe : probes) {
    const std::optional<SeenSurface> seen = seenSurface(scene, materials, probe);
    if (!seen) continue;
    const Ray& ray = seen->ray;
    const SurfaceHit* hit = &seen->hit;
    // The side the camera sees.
    const Vec3f n =
        dot(hit->geometricNormal, ray.direction) > 0 ? -hit->geometricNormal : hit->geometricNormal;
    const Vec3f p = hit->position;
    const float cosFront = -dot(ray.direction, hit->geometricNormal);
    double e = kPi * luminance(emittedRadiance(materials, hit->material, hit->uv, hit->uv1, cosFront));
    for (const PunctualLight& l : desc.lights) {
      const double intensity = std::max(0.0f, luminance(l.intensity));
      if (l.type == PunctualLight::Type::Directional) {
        e += intensity * std::max(0.0f, -dot(n, l.direction));
        continue;
      }
      const Vec3f d = l.position - p;
      const float dist2 = lengthSquared(d);
      if (!(dist2 > 0)) continue;
      const float dist = std::sqrt(dist2);
      const Vec3f wi = d / dist;
      double scale = rangeWindow(l, dist) / dist2;
      if (l.type == PunctualLight::Type::Spot) scale *= spotAttenuation(l, -wi);
      e += intensity * scale * std::max(0.0f, dot(n, wi));
    }
    for (std::size_t k = 0; k < triangles.size(); k += stride) {
      const EmissiveTriangle& t = triangles[k];
      const Vec3f d = t.centroid - p;
      const float dist2 = lengthSquared(d);
      if (!(dist2 > 0)) continue;
      const Vec3f wi = d / std::sqrt(dist2);
      const float cosLight = -dot(wi, t.normal);
      const double cosL = t.doubleSided ? std::abs(cosLight) : std::max(0.0f, cosLight);
      const double cosP = std::max(0.0f, dot(n, wi));
      e += double(stride) * std::min(t.power * cosL * cosP / dist2, kPi * t.radiance);
    }
    levels.push_back(e);
  }
  if (levels.empty()) return std::nullopt;
  const auto mid = levels.begin() + std::ptrdiff_t(levels.size() / 2);
  std::nth_element(levels.begin(), mid, levels.end());
  return *mid;
}

}  // namespace lensrt
