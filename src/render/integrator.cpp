#include "render/integrator.h"

#include <algorithm>
#include <cmath>

#include "render/dielectric_bsdf.h"
#include "render/ggx.h"
#include "render/gltf_bsdf.h"

namespace lensrt {
namespace {

// Offset along the geometric normal, scaled to the coordinates' magnitude so
// that the next ray does not re-hit its own surface through rounding.
float offsetScale(const Vec3f& p) {
  return 2e-4f * std::max({1.0f, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}
Vec3f offsetOrigin(const Vec3f& p, const Vec3f& n) {
  return p + n * offsetScale(p);
}

// Aims `ray` from its origin at the light point `target`, stopping short of it
// by the same offset so that the emitter does not shadow itself; returns the
// distance to the target.
float aimAt(Ray& ray, const Vec3f& target) {
  const Vec3f d = target - ray.origin;
  const float len = length(d);
  ray.direction = d / len;
  ray.tMax = len * (1 - 1e-4f) - offsetScale(target);
  return len;
}

// KHR_materials_volume's absorption coefficient at the sample's wavelengths:
// sigma = -ln(c) / d of the attenuation colour c, upsampled as a reflectance.
Spectrum attenuationCoefficient(const Material& m, const SampledWavelengths& lambda) {
  if (!lambda.spectral()) return Spectrum(m.attenuationCoefficient());
  if (!(m.attenuationDistance > 0) || !std::isfinite(m.attenuationDistance)) return Spectrum(0.0f);
  Spectrum sigma = lambda.reflectance(m.attenuationColor);
  for (float& c : sigma.v) c = -std::log(std::clamp(c, 1e-6f, 1.0f)) / m.attenuationDistance;
  return sigma;
}

}  // namespace

float powerHeuristic(float pdfA, float pdfB) {
  if (std::isinf(pdfA)) return 1.0f;
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0 ? a / (a + b) : 0.0f;
}

Integrator::Integrator(const RenderScene& scene, const MaterialTable& materials, const LightSet& lights,
                       const Environment& environment, const IntegratorSettings& settings)
    : scene_(scene), materials_(materials), lights_(lights), environment_(environment), settings_(settings) {
  for (const Material& m : scene.desc().materials)
    thinGlass_ = thinGlass_ || (m.transmission > 0 && m.thinWalled());
}

Spectrum Integrator::thinGlassTransmittance(Ray ray, const Vec3f& target, bool finite,
                                            const SampledWavelengths& lambda) const {
  Spectrum t{1.0f};
  for (int crossings = 0; crossings < 16; ++crossings) {
    const std::optional<SurfaceHit> hit = scene_.intersect(ray);
    if (!hit) return t;
    const Material& m = materials_.material(hit->material);
    if (!(m.transmission > 0) || !m.thinWalled()) return Spectrum(0.0f);
    // What the sheet lets through straight: the transmitting share of the
    // dielectric, less its Fresnel reflection, tinted by the base colour.
    const ShadingPoint sp = evaluateMaterial(materials_, *hit, -ray.direction, lambda);
    // Only smooth sheets: through a rough one the light is scattered, and
    // paths that scatter at the sheet and aim at the light from there (next-
    // event estimation at the sheet) already carry it.
    if (ggx::alphaFromRoughness(sp.bsdf.base.roughness) > ggx::kMinAlpha) return Spectrum(0.0f);
    const float cosine = std::abs(dot(ray.direction, sp.geometricNormal));
    const float reflected = sp.bsdf.base.specularWeight * fresnelDielectric(cosine, std::max(1.0f, m.ior));
    t *= sp.bsdf.baseColor() * ((1 - sp.bsdf.base.metallic) * sp.bsdf.transmission * (1 - reflected));
    if (!(maxComponent(t) > 0)) return Spectrum(0.0f);
    // On past the sheet, toward the same light point.
    ray.origin = offsetOrigin(hit->position, -sp.geometricNormal);
    if (finite && !(aimAt(ray, target) > offsetScale(target))) return t;  // past the light
  }
  return Spectrum(0.0f);
}

std::uint32_t Integrator::sampleDimensions() const {
  // The camera's block, then one block per scattering vertex (depth < maxDepth).
  const std::int64_t last =
      settings_.maxDepth > 0
          ? std::int64_t(kDimFirstBounce) + std::int64_t(settings_.maxDepth - 1) * kDimensionsPerBounce
          : 0;
  return std::uint32_t(std::min<std::int64_t>(last + SampleBlock::kDims, std::int64_t{1} << 30));
}

PathSample Integrator::trace(const Ray& cameraRay, const Sampler& sampler, SampledWavelengths lambda,
                             bool afterLensReflection) const {
  PathSample out;
  Spectrum radiance{0.0f};
  Rgb film{0, 0, 0};  // what the path gathered before it dropped wavelengths
  Spectrum beta = lambda.liveLanes();
  Ray ray = cameraRay;
  float prevBsdfPdf = 0;
  Vec3f prevPosition, prevNormal;  // the last scattering vertex, for the light pick's MIS density
  // Absorption coefficient of the medium the path is in (KHR_materials_volume):
  // set when it refracts into a volume through a front face, cleared when it
  // leaves through a back face. Camera paths start in air.
  Spectrum sigma{0.0f};
  const auto absorbed = [&](float distance) { return exp(sigma * -distance); };

  for (int depth = 0;; ++depth) {
    if (settings_.observer) settings_.observer->traced(depth == 0 ? RayKind::Camera : RayKind::Bounce, ray);
    const std::optional<SurfaceHit> hit = scene_.intersect(ray);
    if (!hit) {
      const Rgb le = environment_.eval(ray.direction);
      // The sun seen through a lens reflection is the flare light pass's.
      if (maxComponent(le) > 0 && !(depth == 0 && afterLensReflection && environment_.inSun(ray.direction))) {
        const float w =
            depth == 0 ? 1.0f : powerHeuristic(prevBsdfPdf, lights_.pdfEnvironment(ray.direction));
        radiance += beta * lambda.illuminant(le) * w;
      }
      break;
    }
    if (maxComponent(sigma) > 0) beta *= absorbed(hit->t);
    const Vec3f wo = -ray.direction;
    if (lambda.spectral() && !lambda.secondaryTerminated() &&
        isDispersiveVolume(materials_.material(hit->material))) {
      // Refraction at this surface depends on the wavelength: the path goes on
      // at the hero alone. What it has gathered so far keeps its four.
      film += lambda.toFilm(radiance);
      radiance = Spectrum(0.0f);
      lambda.terminateSecondary();
      beta *= lambda.liveLanes();
    }
    const ShadingPoint sp = evaluateMaterial(materials_, *hit, wo, lambda);
    if (depth == 0) {
      out.hit = true;
      out.distance = hit->t;
      out.position = hit->position;
      out.objectPosition = hit->objectPosition;
      out.uv = hit->uv;
      out.normal = sp.frame.n;
      out.albedo = sp.albedo;
      out.instance = hit->instance;
      out.material = hit->material;
      out.primitive = hit->primitive;
      out.barycentric = hit->barycentric;
    }
    // A still emitter seen through a lens reflection is the flare light pass's.
    if (maxComponent(sp.emission) > 0 &&
        !(depth == 0 && afterLensReflection && lights_.stillEmitter(hit->instance, hit->primitive))) {
      float w = 1.0f;
      if (depth > 0)
        w = powerHeuristic(prevBsdfPdf,
                           lights_.pdfTriangle(hit->instance, hit->primitive, prevPosition, prevNormal,
                                               hit->position, hit->geometricNormal, ray.time));
      radiance += beta * sp.emission * w;
    }
    if (depth >= settings_.maxDepth) break;

    const GltfBsdf bsdf(sp.bsdf, sp.frame, sp.coatFrame, wo);
    const Vec3f& ng = sp.geometricNormal;
    // A direction is usable when the geometric and the shading normal agree on
    // its side (otherwise a reflection would pass through the surface or a
    // refraction stay in front of it).
    const auto consistent = [&](const Vec3f& wi) { return (dot(wi, ng) > 0) == (dot(wi, sp.frame.n) > 0); };
    const auto originToward = [&](const Vec3f& wi) {
      return offsetOrigin(hit->position, dot(wi, ng) > 0 ? ng : -ng);
    };
    // This vertex's sample values, all at once (see SampleBlock).
    const SampleBlock u = sampler.block(kDimFirstBounce + std::uint32_t(depth) * kDimensionsPerBounce);

    // Next-event estimation.
    if (!lights_.empty()) {
      const std::optional<LightSample> ls =
          lights_.sample(hit->position, sp.frame.n, u.get1D(0), u.get2D(1), ray.time);
      if (ls && receivesLight(sp, bsdf, ls->wi)) {
        const BsdfValue bv = bsdf.evalPdf(wo, ls->wi);
        const Spectrum f = bv.f * std::abs(dot(ls->wi, sp.frame.n));
        if (maxComponent(f) > 0) {
          Ray shadow{originToward(ls->wi), ls->wi, 0.0f, kInfinityF, ray.time};
          // A light at a point: aim from the offset origin at that point itself.
          const bool finite = std::isfinite(ls->distance);
          const Vec3f target = finite ? hit->position + ls->wi * ls->distance : Vec3f{};
          if (finite) aimAt(shadow, target);

          if (settings_.observer) settings_.observer->traced(RayKind::Shadow, shadow);
          // A lamp's light on what a lens-reflected camera ray meets first,
          // with nothing in between, is the flare light pass's (its lit
          // surfaces' ghosts). Through a glass sheet it stays here: the
          // pass's rays stop at the sheet.
          // Punctual lights shine through thin-walled glass (see
          // thinGlassTransmittance); every other shadow ray stops at anything.
          const bool passLamp = depth == 0 && afterLensReflection && ls->flareLamp;
          const Spectrum visible = passLamp ? (!scene_.occluded(shadow) || !thinGlass_
                                                   ? Spectrum(0.0f)
                                                   : thinGlassTransmittance(shadow, target, finite, lambda))
                                   : ls->delta && thinGlass_
                                       ? thinGlassTransmittance(shadow, target, finite, lambda)
                                       : Spectrum(scene_.occluded(shadow) ? 0.0f : 1.0f);
          if (maxComponent(visible) > 0) {
            const float w = ls->delta ? 1.0f : powerHeuristic(ls->pdf, bv.pdf);
            Spectrum contribution = beta * f * lambda.illuminant(ls->radiance) * visible * (w / ls->pdf);
            // Inside a medium the light's segment is absorbed too (a light
            // inside a volume; lights outside are behind its surface).
            if (maxComponent(sigma) > 0 && finite) contribution *= absorbed(ls->distance);
            radiance += contribution;
          }
        }
      }
    }

    // Continue the path by sampling the BSDF.
    const std::optional<BsdfSample> bs = bsdf.sample(wo, u.get1D(2), u.get2D(3));
    if (!bs) break;
    const Vec3f wi = bs->wi;
    if (!consistent(wi)) break;  // a shading-normal artefact
    const bool transmitted = dot(wi, ng) < 0;
    beta *= bs->f * (std::abs(dot(wi, sp.frame.n)) / bs->pdf);
    prevBsdfPdf = bs->pdf;
    prevPosition = hit->position;
    prevNormal = sp.frame.n;
    ray = Ray{originToward(wi), wi, 0.0f, kInfinityF, ray.time};
    if (transmitted) {
      const Material& m = materials_.material(hit->material);
      if (!m.thinWalled()) sigma = sp.frontFace ? attenuationCoefficient(m, lambda) : Spectrum(0.0f);
    }

    if (depth + 1 >= settings_.rouletteDepth) {
      const float survive = std::min(1.0f, maxComponent(beta));
      if (!(survive > 0)) break;
      if (survive < 1) {
        if (u.get1D(4) >= survive) break;
        beta = beta / survive;
      }
    }
  }
  out.radiance = film + lambda.toFilm(radiance);
  return out;
}

}  // namespace lensrt
