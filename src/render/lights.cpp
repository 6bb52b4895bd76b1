#include "render/lights.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/constants.h"
#include "scene/surface_alpha.h"

namespace lensrt {

float spotAttenuation(const PunctualLight& light, const Vec3f& towardPoint) {
  // KHR_lights_punctual's reference: saturate(cd * scale + offset)^2.
  const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
  const float scale = 1.0f / std::max(1e-3f, cosInner - cosOuter);
  const float t = std::clamp((dot(light.direction, towardPoint) - cosOuter) * scale, 0.0f, 1.0f);
  return t * t;
}

float rangeWindow(const PunctualLight& light, float distance) {
  if (!(light.range > 0)) return 1.0f;
  const float r = distance / light.range;
  const float w = std::clamp(1 - r * r * r * r, 0.0f, 1.0f);
  return w * w;
}

const char* lightSamplingName(LightSampling sampling) {
  return sampling == LightSampling::Tree ? "tree" : "power";
}

std::optional<LightSampling> parseLightSampling(std::string_view name) {
  if (name == "tree") return LightSampling::Tree;
  if (name == "power") return LightSampling::Power;
  return std::nullopt;
}

namespace {

// Where and how a point or spot light shines, for the light tree. phi is
// 4 pi I for both: the cone, not phi, says where a spot does not reach.
LightBounds punctualBounds(const PunctualLight& l) {
  LightBounds b;
  b.bounds.extend(l.position);
  b.phi = 4 * kPiF * std::max(0.0f, luminance(l.intensity));
  if (l.type == PunctualLight::Type::Spot) {
    // Full inside the inner cone, nothing past the outer one; a milliradian
    // more, so that rounding never calls a lit point unreachable.
    const float outer = std::clamp(l.outerConeAngle, 0.0f, kPiF);
    const float inner = std::clamp(l.innerConeAngle, 0.0f, outer);
    b.axis = l.direction;
    b.cosThetaO = std::cos(inner);
    b.cosThetaE = std::cos(std::min(outer - inner + 1e-3f, kPiF));
  } else {
    b.cosThetaO = -1;  // every direction
    b.cosThetaE = 0;
  }
  return b;
}

}  // namespace

LightSet::LightSet(const MaterialTable& materials, const Environment& environment, const Bounds3f& bounds,
                   LightSampling sampling)
    : materials_(&materials), environment_(&environment), sampling_(sampling) {
  const SceneDesc& scene = materials.scene();
  instanceFirstTriangle_.assign(scene.instances.size(), -1);
  std::vector<float> power;
  for (const PunctualLight& l : scene.lights) {
    const float i = std::max(0.0f, luminance(l.intensity));
    const float radius = bounds.empty() ? 1.0f : 0.5f * length(bounds.diagonal());
    switch (l.type) {
      case PunctualLight::Type::Point:
        power.push_back(4 * kPiF * i);
        break;
      case PunctualLight::Type::Spot:
        power.push_back(2 * kPiF * (1 - std::cos(0.5f * (l.innerConeAngle + l.outerConeAngle))) * i);
        break;
      case PunctualLight::Type::Directional:
        power.push_back(kPiF * radius * radius * i);
        break;
    }
  }
  firstTriangle_ = power.size();
  motionSteps_ = std::size_t(std::max(0, scene.motionSteps));
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const MeshInstance& inst = scene.instances[k];
    if (inst.mesh < 0 || std::size_t(inst.mesh) >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[inst.mesh];
    const Material& m = materials.material(mesh.material);
    if (!m.isEmissive()) continue;
    instanceFirstTriangle_[k] = std::int64_t(triangles_.size());
    // A mirroring transform reverses the winding; glTF says the front face flips with it.
    const float handed = inst.worldFromObject.determinant3x3() < 0 ? -1.0f : 1.0f;
    // Textures can only dim the factor (texels are at most 1 in practice), so
    // power from the factor is a fair picking weight.
    const float le = luminance(m.emissive) * (m.doubleSided ? 2.0f : 1.0f);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const std::uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1],
                          i2 = mesh.indices[3 * t + 2];
      Triangle tri;
      tri.p0 = inst.worldFromObject.point(mesh.positions[i0]);
      tri.e1 = inst.worldFromObject.point(mesh.positions[i1]) - tri.p0;
      tri.e2 = inst.worldFromObject.point(mesh.positions[i2]) - tri.p0;
      const Vec3f c = cross(tri.e1, tri.e2);
      const float len = length(c);
      tri.area = 0.5f * len;
      tri.normal = len > 0 ? c * (handed / len) : Vec3f{0, 0, 1};
      // The UV set the emissive texture reads (TEXCOORD_0 or TEXCOORD_1).
      const std::vector<Vec2f>& uvs = m.emissiveTexture.texCoord == 1 ? mesh.uvs1 : mesh.uvs;
      if (!uvs.empty()) {
        tri.uv0 = uvs[i0];
        tri.uv1 = uvs[i1];
        tri.uv2 = uvs[i2];
      }
      tri.material = mesh.material;
      tri.mesh = inst.mesh;
      tri.instance = int(k);
      tri.prim = static_cast<unsigned>(t);
      tri.handed = handed;
      if (inst.moves()) {
        tri.firstStep = steps_.size();
        for (const MeshInstance::Step& step : inst.motion) {
          const std::vector<Vec3f>& at = scene.meshes[step.mesh].positions;
          const Vec3f q0 = step.worldFromObject.point(at[i0]);
          steps_.push_back(
              {q0, step.worldFromObject.point(at[i1]) - q0, step.worldFromObject.point(at[i2]) - q0});
        }
      }
      triangles_.push_back(tri);
      power.push_back(std::isfinite(tri.area) ? kPiF * tri.area * le : 0.0f);
    }
  }
  environmentIndex_ = power.size();
  if (!environment.isBlack()) {
    const float radius = bounds.empty() ? 1.0f : std::max(1e-3f, 0.5f * length(bounds.diagonal()));
    // Flux of a uniform sky of radiance L through a disk the size of the scene.
    power.push_back(kPiF * kPiF * radius * radius * environment.averageLuminance());
  }
  pick_ = Distribution1D(power);
  if (sampling_ == LightSampling::Tree) buildTree(power);

  // The dominant light's colour: each punctual light, each emissive
  // material's triangles together, the environment, by the power above.
  std::vector<std::pair<double, Rgb>> sources;
  for (std::size_t i = 0; i < scene.lights.size(); ++i)
    sources.emplace_back(power[i], scene.lights[i].intensity);
  std::map<int, std::pair<double, Rgb>> byMaterial;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    auto& [sum, colour] = byMaterial[triangles_[t].material];
    sum += power[firstTriangle_ + t];
    colour = materials.material(triangles_[t].material).emissive;
  }
  for (const auto& [material, source] : byMaterial) sources.push_back(source);
  if (!environment.isBlack()) sources.emplace_back(power.back(), environment.averageRadiance());
  double best = 0;
  for (const auto& [p, colour] : sources)
    if (p > best && maxComponent(colour) > 0) {
      best = p;
      dominantColour_ = colour;
    }
}

void LightSet::buildTree(const std::vector<float>& power) {
  const std::vector<PunctualLight>& punctual = materials_->scene().lights;
  std::vector<LightBounds> lights(power.size());        // phi 0: not in the tree
  std::vector<std::int32_t> emitter(power.size(), -1);  // a triangle's instance
  std::vector<float> topWeights;
  topSlot_.assign(power.size(), std::size_t(-1));
  const auto outside = [&](std::size_t i) {
    topSlot_[i] = outside_.size();
    outside_.push_back(i);
    topWeights.push_back(power[i]);
  };
  double treePower = 0;
  for (std::size_t i = 0; i < firstTriangle_; ++i) {
    if (punctual[i].type == PunctualLight::Type::Directional) {
      outside(i);
    } else if (power[i] > 0) {
      lights[i] = punctualBounds(punctual[i]);
      // Moving: everywhere it goes, a spot's cone widened by how far it turns.
      float turn = 0;
      for (const PunctualLight::Step& step : punctual[i].motion) {
        lights[i].bounds.extend(step.position);
        turn = std::max(turn, std::acos(std::clamp(dot(step.direction, punctual[i].direction), -1.0f, 1.0f)));
      }
      if (turn > 0 && punctual[i].type == PunctualLight::Type::Spot)
        lights[i].cosThetaO = std::cos(std::min(kPiF, std::acos(lights[i].cosThetaO) + turn + 1e-3f));
      treePower += power[i];
    }
  }
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const float p = power[firstTriangle_ + t];
    if (!(p > 0)) continue;
    const Triangle& tri = triangles_[t];
    LightBounds& b = lights[firstTriangle_ + t];
    b.bounds.extend(tri.p0);
    b.bounds.extend(tri.p0 + tri.e1);
    b.bounds.extend(tri.p0 + tri.e2);
    b.axis = tri.normal;
    b.cosThetaO = 1;  // one normal
    if (tri.firstStep != kNoSteps) {
      // Moving: wherever it goes and however it turns during the shutter.
      for (std::size_t k = 0; k < motionSteps_; ++k) {
        const TriangleStep& s = steps_[tri.firstStep + k];
        b.bounds.extend(s.p0);
        b.bounds.extend(s.p0 + s.e1);
        b.bounds.extend(s.p0 + s.e2);
        if (const auto normal = unitVector(cross(s.e1, s.e2) * tri.handed))
          b.cosThetaO = std::min(b.cosThetaO, std::max(-1.0f, dot(*normal, tri.normal) - 1e-3f));
        else
          b.cosThetaO = -1;
      }
    }
    b.cosThetaE = 0;  // Lambertian: to the horizon
    b.twoSided = materials_->material(tri.material).doubleSided;
    b.phi = b.twoSided ? 0.5f * p : p;  // what one side emits, as one side is what a point sees
    emitter[firstTriangle_ + t] = tri.instance;
    treePower += p;
  }
  for (std::size_t i = environmentIndex_; i < power.size(); ++i) outside(i);
  topWeights.push_back(float(treePower));
  top_ = Distribution1D(topWeights);
  tree_ = LightTree(lights, emitter);
}

float LightSet::pickProbability(std::size_t i, const Vec3f& p, const Vec3f& n) const {
  if (i >= pick_.size()) return 0;
  if (sampling_ == LightSampling::Power) return pick_.probability(i);
  if (topSlot_[i] != std::size_t(-1)) return top_.probability(topSlot_[i]);
  return top_.probability(outside_.size()) * tree_.pmf(p, n, i);
}

LightSet::Triangle LightSet::posed(const Triangle& t, float time) const {
  if (t.firstStep == kNoSteps || motionSteps_ < 2) return t;
  const float f = std::clamp(time, 0.0f, 1.0f) * float(motionSteps_ - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(f), motionSteps_ - 2);
  const float a = f - float(k);
  const TriangleStep &s0 = steps_[t.firstStep + k], &s1 = steps_[t.firstStep + k + 1];
  Triangle at = t;
  at.p0 = s0.p0 * (1 - a) + s1.p0 * a;
  at.e1 = s0.e1 * (1 - a) + s1.e1 * a;
  at.e2 = s0.e2 * (1 - a) + s1.e2 * a;
  const Vec3f c = cross(at.e1, at.e2);
  const float len = length(c);
  at.area = 0.5f * len;
  at.normal = len > 0 ? c * (t.handed / len) : t.normal;
  return at;
}

PunctualLight LightSet::posed(const PunctualLight& l, float time) const {
  if (l.motion.size() < 2) return l;
  const float f = std::clamp(time, 0.0f, 1.0f) * float(l.motion.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(f), l.motion.size() - 2);
  const float a = f - float(k);
  PunctualLight at = l;
  at.position = l.motion[k].position * (1 - a) + l.motion[k + 1].position * a;
  if (const auto d = unitVector(l.motion[k].direction * (1 - a) + l.motion[k + 1].direction * a))
    at.direction = *d;
  return at;
}

bool isFlareLamp(const PunctualLight& light) {
  return light.type != PunctualLight::Type::Directional && light.motion.size() < 2;
}

std::optional<LightSample> LightSet::samplePunctual(const PunctualLight& l, const Vec3f& p) const {
  if (l.type == PunctualLight::Type::Directional) {
    return LightSample{-l.direction, kInfinityF, l.intensity, 1.0f, true};
  }
  const Vec3f d = l.position - p;
  const float dist2 = lengthSquared(d);
  if (!(dist2 > 0)) return std::nullopt;
  const float dist = std::sqrt(dist2);
  const Vec3f wi = d / dist;
  float scale = rangeWindow(l, dist) / dist2;
  if (l.type == PunctualLight::Type::Spot) scale *= spotAttenuation(l, -wi);
  if (!(scale > 0)) return std::nullopt;
  return LightSample{wi, dist, l.intensity * scale, 1.0f, true, isFlareLamp(l)};
}

std::optional<LightSample> LightSet::sampleTriangle(const Triangle& t, const Vec3f& p, const Vec2f& u) const {
  // Uniform on the triangle (square-root parameterisation).
  const float su = std::sqrt(u.x);
  const float b1 = 1 - su, b2 = u.y * su;
  const Vec3f q = t.p0 + t.e1 * b1 + t.e2 * b2;
  const Vec3f d = q - p;
  const float dist2 = lengthSquared(d);
  if (!(dist2 > 0) || !(t.area > 0)) return std::nullopt;
  const float dist = std::sqrt(dist2);
  const Vec3f wi = d / dist;
  const float cosLight = -dot(wi, t.normal);  // > 0 when p sees the front
  const Vec2f uv = t.uv0 * (1 - b1 - b2) + t.uv1 * b1 + t.uv2 * b2;
  // uvs hold the emissive slot's set. An alpha-masked or blended emitter is
  // there only where (MASK) or as often as (BLEND) its alpha says, as a
  // BSDF ray hitting it finds.
  const SceneDesc& scene = materials_->scene();
  const Rgb le =
      emittedRadiance(*materials_, t.material, uv, uv, cosLight) *
      surfaceCoverage(scene, scene.meshes[t.mesh], materials_->material(t.material), t.prim, b1, b2);
  if (!(maxComponent(le) > 0) || std::abs(cosLight) < 1e-7f) return std::nullopt;
  return LightSample{wi, dist, le, dist2 / (std::abs(cosLight) * t.area), false};
}

std::optional<LightSample> LightSet::sample(const Vec3f& p, const Vec3f& n, float uPick, const Vec2f& u,
                                            float time) const {
  if (pick_.empty()) return std::nullopt;
  std::size_t i = 0;
  float pickPdf = 0;
  if (sampling_ == LightSampling::Power) {
    i = pick_.sample(uPick);
    pickPdf = pick_.probability(i);
  } else {
    // Without directional lights or an environment the tree is all there is.
    float uTree = uPick;
    const std::size_t slot = outside_.empty() ? 0 : top_.sample(uPick, &uTree);
    if (slot < outside_.size()) {
      i = outside_[slot];
      pickPdf = top_.probability(slot);
    } else {
      const std::optional<LightPick> pick = tree_.sample(p, n, uTree);
      if (!pick) return std::nullopt;
      i = pick->light;
      // As pickProbability multiplies them, so that the two agree to the bit.
      pickPdf = top_.probability(slot) * pick->pmf;
    }
  }
  std::optional<LightSample> s;
  if (i < firstTriangle_) {
    // A still light as it is: posing copies it (its name and steps), per sample.
    const PunctualLight& l = materials_->scene().lights[i];
    s = l.motion.size() < 2 ? samplePunctual(l, p) : samplePunctual(posed(l, time), p);
  } else if (i < environmentIndex_) {
    s = sampleTriangle(posed(triangles_[i - firstTriangle_], time), p, u);
  } else if (auto e = environment_->sample(u)) {
    s = LightSample{e->direction, kInfinityF, e->radiance, e->pdf, false};
  }
  if (!s || !(s->pdf > 0)) return std::nullopt;
  s->pdf *= pickPdf;
  return s;
}

float LightSet::pdfTriangle(int instance, unsigned primitive, const Vec3f& p, const Vec3f& n,
                            const Vec3f& lightPoint, const Vec3f& lightNormal, float time) const {
  if (instance < 0 || std::size_t(instance) >= instanceFirstTriangle_.size()) return 0;
  const std::int64_t first = instanceFirstTriangle_[instance];
  if (first < 0) return 0;
  const std::size_t k = std::size_t(first) + primitive;
  if (k >= triangles_.size()) return 0;
  const Triangle& stored = triangles_[k];
  const float area = stored.firstStep == kNoSteps ? stored.area : posed(stored, time).area;
  const Vec3f d = lightPoint - p;
  const float dist2 = lengthSquared(d);
  const float cosLight = std::abs(dot(d, lightNormal)) / std::sqrt(dist2);
  if (!(cosLight > 0) || !(area > 0)) return 0;
  return pickProbability(firstTriangle_ + k, p, n) * dist2 / (cosLight * area);
}

bool LightSet::stillEmitter(int instance, unsigned primitive) const {
  if (instance < 0 || std::size_t(instance) >= instanceFirstTriangle_.size()) return false;
  const std::int64_t first = instanceFirstTriangle_[std::size_t(instance)];
  if (first < 0) return false;
  const std::size_t k = std::size_t(first) + primitive;
  return k < triangles_.size() && triangles_[k].firstStep == kNoSteps;
}

LightSet::EmissiveTriangle LightSet::emissiveTriangle(std::size_t t) const {
  const Triangle& tri = triangles_[t];
  const Material& m = materials_->material(tri.material);
  return {tri.p0,        tri.e1,
          tri.e2,        tri.normal,
          tri.area,      luminance(m.emissive),
          m.doubleSided, tri.firstStep == kNoSteps,
          tri.instance};
}

float LightSet::pdfEnvironment(const Vec3f& direction) const {
  if (environment_->isBlack() || environmentIndex_ >= pick_.size()) return 0;
  // Not pickProbability: the environment's pick depends on no point.
  const float pick = sampling_ == LightSampling::Power ? pick_.probability(environmentIndex_)
                                                       : top_.probability(topSlot_[environmentIndex_]);
  return pick * environment_->pdf(direction);
}

}  // namespace lensrt
