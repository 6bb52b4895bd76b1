#include "render/gltf_bsdf.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lensrt {
namespace {

BsdfParams opaquePart(const GltfBsdfParams& p) {
  BsdfParams b = p.base;
  b.opaqueWeight = 1 - std::clamp(p.transmission, 0.0f, 1.0f);
  return b;
}

}  // namespace

GltfBsdf::GltfBsdf(const GltfBsdfParams& p, const Frame& shading, const Frame& coat)
    : GltfBsdf(p, shading, coat, Vec3f{1, 1, 1} * std::numeric_limits<float>::quiet_NaN()) {}

GltfBsdf::GltfBsdf(const GltfBsdfParams& p, const Frame& shading, const Frame& coat, const Vec3f& wo)
    : shading_(shading),
      coat_(coat),
      transmission_((1 - std::clamp(p.base.metallic, 0.0f, 1.0f)) * std::clamp(p.transmission, 0.0f, 1.0f)),
      clearcoat_(std::clamp(p.clearcoat, 0.0f, 1.0f)),
      sheenMax_(std::clamp(maxComponent(p.sheenColor), 0.0f, 1.0f)),
      wo_(wo),
      woLocal_(shading.toLocal(wo)),
      woCoat_(coat.toLocal(wo)),
      base_(opaquePart(p), woLocal_.z) {
  if (transmission_ > 0) dielectric_.emplace(p.dielectric);
  if (clearcoat_ > 0) coatLobe_.emplace(p.clearcoatRoughness);
  if (sheenMax_ > 0) sheen_.emplace(p.sheenColor, p.sheenRoughness);
  choice_ = computeChoice(woLocal_, woCoat_);
}

float GltfBsdf::coatScale(const Vec3f& woCoat, const Vec3f& wiCoat) const {
  if (clearcoat_ <= 0) return 1;
  const float e = std::max(coatLobe_->albedo(std::abs(woCoat.z)), coatLobe_->albedo(std::abs(wiCoat.z)));
  return 1 - clearcoat_ * e;
}

float GltfBsdf::sheenScale(const Vec3f& wo, const Vec3f& wi) const {
  if (sheenMax_ <= 0) return 1;
  const float e = std::max(sheen_->albedo(std::abs(wo.z)), sheen_->albedo(std::abs(wi.z)));
  return std::max(0.0f, 1 - sheenMax_ * e);
}

GltfBsdf::Choice GltfBsdf::choose(const Vec3f& wo) const {
  return wo == wo_ ? choice_ : computeChoice(shading_.toLocal(wo), coat_.toLocal(wo));
}

GltfBsdf::Choice GltfBsdf::computeChoice(const Vec3f& woLocal, const Vec3f& woCoat) const {
  Choice c;
  float rest = 1;
  if (clearcoat_ > 0 && woCoat.z > 0) {
    c.coat = clearcoat_ * coatLobe_->albedo(woCoat.z);
    rest -= c.coat;
  }
  if (sheenMax_ > 0 && woLocal.z > 0) {
    c.sheen = rest * sheenMax_ * sheen_->albedo(woLocal.z);
    rest -= c.sheen;
  }
  c.trans = rest * transmission_;
  c.base = rest - c.trans;
  return c;
}

// eval and pdf are the two halves of evalPdf (the renderer wants both at once).
Spectrum GltfBsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  return evalPdf(wo, wi).f;
}

float GltfBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  return evalPdf(wo, wi).pdf;
}

BsdfValue GltfBsdf::evalPdf(const Vec3f& wo, const Vec3f& wi) const {
  const Choice c = choose(wo);
  const Vec3f woL = local(wo), wiL = shading_.toLocal(wi);
  const BsdfValue b = base_.evalPdf(woL, wiL);
  // The layers' values and the lobes' densities weighted by their choice.
  Spectrum f = b.f;
  float p = 0;
  if (c.base > 0) p += c.base * b.pdf;
  if (transmission_ > 0) f += dielectric_->eval(woL, wiL) * transmission_;
  if (c.trans > 0) p += c.trans * dielectric_->pdf(woL, wiL);
  if (sheenMax_ > 0) f = sheen_->eval(woL, wiL) + f * sheenScale(woL, wiL);
  if (c.sheen > 0) p += c.sheen * sheen_->pdf(woL, wiL);
  if (clearcoat_ > 0) {
    const Vec3f woC = coatLocal(wo), wiC = coat_.toLocal(wi);
    f = coatLobe_->eval(woC, wiC) * clearcoat_ + f * coatScale(woC, wiC);
    if (c.coat > 0) p += c.coat * coatLobe_->pdf(woC, wiC);
  }
  return {f, p};
}

std::optional<BsdfSample> GltfBsdf::sample(const Vec3f& wo, float uLobe, const Vec2f& u) const {
  const Choice c = choose(wo);
  std::optional<BsdfSample> s;
  bool coatFrame = false;
  // Pick a lobe with uLobe, then rescale it to [0, 1) for the lobe's own choice.
  float x = uLobe;
  if (x < c.coat) {
    s = coatLobe_->sample(coatLocal(wo), u);
    coatFrame = true;
  } else if ((x -= c.coat) < c.sheen) {
    s = sheen_->sample(local(wo), u);
  } else if ((x -= c.sheen) < c.trans) {
    s = dielectric_->sample(local(wo), x / c.trans, u);
  } else {
    x -= c.trans;
    if (!(c.base > 0)) return std::nullopt;
    s = base_.sample(local(wo), std::min(x / c.base, 0.99999994f), u);
  }
  if (!s) return std::nullopt;
  const Vec3f wi = normalize((coatFrame ? coat_ : shading_).toWorld(s->wi));
  // Single-lobe materials (the common case) keep the lobe's own values.
  if (c.base == 1 || c.trans == 1) return BsdfSample{wi, s->f, s->pdf};
  const BsdfValue v = evalPdf(wo, wi);
  if (!(v.pdf > 0)) return std::nullopt;
  return BsdfSample{wi, v.f, v.pdf};
}

}  // namespace lensrt
