// The whole glTF material as one BSDF: the metallic-roughness BRDF (bsdf.h)
// with KHR_materials_transmission's dielectric lobe in place of the share
// `transmission` of its dielectric diffuse (dielectric_bsdf.h), under a sheen
// layer (sheen_bsdf.h), under a clearcoat (clearcoat_bsdf.h), as the glTF
// extensions layer them:
//   f = coat + (1 - c E_c) [sheen + (1 - s E_s) (opaque BRDF + transmission)]
// where c is the clearcoat factor, s = max(sheenColor), and each E is its
// lobe's directional albedo taken at the larger of its values for wo and wi
// (glTF takes it at wo alone; the larger keeps the BSDF reciprocal and every
// layer's albedo within the share the layer above leaves).
// Directions are in world space (the lobes have their own frames: the coat's
// normal may come from its own normal map), unit length, pointing away.
#pragma once

#include <optional>

#include "core/frame.h"
#include "core/vec.h"
#include "render/bsdf.h"
#include "render/clearcoat_bsdf.h"
#include "render/dielectric_bsdf.h"
#include "render/sheen_bsdf.h"
#include "render/spectrum.h"

namespace lensrt {

struct GltfBsdfParams {
  BsdfParams base;
  float transmission = 0;  // share of the dielectric that transmits
  DielectricParams dielectric;
  float clearcoat = 0;
  float clearcoatRoughness = 0;
  Spectrum sheenColor{0.0f};
  float sheenRoughness = 0;

  const Spectrum& baseColor() const { return base.baseColor; }
};

class GltfBsdf {
 public:
  // shading: z = the (normal-mapped) shading normal on the viewer's side;
  // coat: z = the clearcoat's normal on the viewer's side.
  GltfBsdf(const GltfBsdfParams& params, const Frame& shading, const Frame& coat);
  // The same BSDF prepared for the view direction wo (the renderer's hit, seen
  // from one direction): wo in each lobe's frame, the lobe choice and what the
  // base lobe needs of wo alone are computed here once. Other directions work
  // as wo too; the values are the same bits either way.
  GltfBsdf(const GltfBsdfParams& params, const Frame& shading, const Frame& coat, const Vec3f& wo);

  Spectrum eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  // Both at once (what eval and pdf give): the next-event estimate needs
  // both, and the base lobe shares its half vector between them.
  BsdfValue evalPdf(const Vec3f& wo, const Vec3f& wi) const;
  // wi of the sample is in world space. Empty when the sample has no density.
  std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, const Vec2f& u) const;
  // True when some light passes to the other side of the surface.
  bool transmits() const { return transmission_ > 0; }

 private:
  struct Choice {
    float coat = 0, sheen = 0, base = 0, trans = 0;  // probabilities, sum 1
  };
  Choice choose(const Vec3f& wo) const;
  Choice computeChoice(const Vec3f& woLocal, const Vec3f& woCoat) const;
  // wo in the shading and the coat frame, prepared when wo is wo_.
  Vec3f local(const Vec3f& wo) const { return wo == wo_ ? woLocal_ : shading_.toLocal(wo); }
  Vec3f coatLocal(const Vec3f& wo) const { return wo == wo_ ? woCoat_ : coat_.toLocal(wo); }
  // 1 - c E_c and 1 - s E_s for the pair of directions (local to each frame).
  float coatScale(const Vec3f& woCoat, const Vec3f& wiCoat) const;
  float sheenScale(const Vec3f& wo, const Vec3f& wi) const;

  Frame shading_, coat_;
  float transmission_;  // (1 - metallic) * transmission
  float clearcoat_;
  float sheenMax_;
  // The prepared view (NaN: none; a NaN never compares equal).
  Vec3f wo_, woLocal_, woCoat_;
  Choice choice_;
  Bsdf base_;
  // The layers a material has: a plain metallic-roughness material builds none.
  std::optional<DielectricBsdf> dielectric_;  // when transmission_ > 0
  std::optional<ClearcoatBsdf> coatLobe_;     // when clearcoat_ > 0
  std::optional<SheenBsdf> sheen_;            // when sheenMax_ > 0
};

}  // namespace lensrt
