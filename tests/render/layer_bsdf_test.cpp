// The sheen and clearcoat lobes and the layered glTF BSDF: normalisation of
// the Charlie distribution, albedo tables against direct integration,
// reciprocity, energy bounds, chi-square tests of the sampling, and the
// layered BSDF reducing exactly to the metallic-roughness BRDF when no
// extension is present.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "bsdf_check_util.h"
#include "core/constants.h"
#include "render/clearcoat_bsdf.h"
#include "render/gltf_bsdf.h"
#include "render/sheen_bsdf.h"

namespace lensrt {
namespace {

using test::integrateSphere;
using test::sphericalDir;

TEST(SheenBsdf, CharlieDistributionIsNormalised) {
  // int D(h) cos(theta_h) dh = 1 over the hemisphere.
  for (const float r : {0.3f, 0.6f, 1.0f}) {
    const SheenBsdf s(Spectrum(1.0f), r);
    const double i =
        integrateSphere([&](const Vec3f& h) { return s.distribution(h) * h.z; }, 0, kPi / 2, 0, 2 * kPi, 400);
    EXPECT_NEAR(i, 1.0, 2e-3) << "roughness " << r;
  }
}

TEST(SheenBsdf, AlbedoTableMatchesIntegralAndIsReciprocal) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  for (const float r : {0.25f, 0.5f, 1.0f}) {
    const SheenBsdf s(Spectrum(1.0f), r);
    for (const double t : {0.0, 45.0, 75.0}) {
      const Vec3f wo = sphericalDir(t * kPi / 180, 0);
      const double e = integrateSphere([&](const Vec3f& wi) { return s.eval(wo, wi)[1] * wi.z; }, 0, kPi / 2,
                                       0, 2 * kPi, 300);
      EXPECT_NEAR(s.albedo(wo.z), e, 0.02) << "roughness " << r << " theta " << t;
      EXPECT_LE(e, 1.0);
    }
    for (int k = 0; k < 50; ++k) {
      const Vec3f a = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Vec3f b = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      EXPECT_NEAR(s.eval(a, b)[1], s.eval(b, a)[1], 1e-5f * std::max(1.0f, s.eval(a, b)[1]));
    }
  }
}

TEST(ClearcoatBsdf, AlbedoTableMatchesIntegral) {
  for (const float r : {0.3f, 0.6f, 1.0f}) {
    const ClearcoatBsdf c(r);
    for (const double t : {0.0, 45.0, 75.0}) {
      const Vec3f wo = sphericalDir(t * kPi / 180, 0);
      const double e = integrateSphere([&](const Vec3f& wi) { return c.eval(wo, wi)[1] * wi.z; }, 0, kPi / 2,
                                       0, 2 * kPi, 400);
      EXPECT_NEAR(c.albedo(wo.z), e, 0.01) << "roughness " << r << " theta " << t;
    }
  }
  // At normal incidence a smooth coat reflects f0 = 0.04 (ior 1.5).
  EXPECT_NEAR(ClearcoatBsdf(0).albedo(1), 0.04, 2e-3);
}

GltfBsdfParams layered(float clearcoat, float sheen, float transmission, float metallic, bool thin) {
  GltfBsdfParams p;
  p.base.baseColor = Spectrum(Rgb{0.9f, 0.7f, 0.5f});
  p.base.roughness = 0.6f;
  p.base.metallic = metallic;
  p.transmission = transmission;
  p.dielectric.eta = 1.4f;
  p.dielectric.roughness = 0.6f;
  p.dielectric.tint = p.base.baseColor;
  p.dielectric.thin = thin;
  p.clearcoat = clearcoat;
  p.clearcoatRoughness = 0.5f;
  p.sheenColor = Spectrum(Rgb{sheen, sheen * 0.5f, sheen});
  p.sheenRoughness = 0.5f;
  return p;
}

// A coat normal tilted away from the shading normal, as a clearcoat normal map makes.
Frame tiltedCoat() {
  return Frame::fromNormal(normalize(Vec3f{0.2f, 0.1f, 1}));
}

TEST(GltfBsdf, WithoutExtensionsIsTheMetallicRoughnessBrdf) {
  BsdfParams base;
  base.baseColor = Spectrum(Rgb{0.8f, 0.5f, 0.3f});
  base.metallic = 0.3f;
  base.roughness = 0.7f;
  GltfBsdfParams p;
  p.base = base;
  const Frame frame = Frame::fromNormal(normalize(Vec3f{0.3f, -0.2f, 1}));
  const GltfBsdf g(p, frame, frame);
  const Bsdf b(base);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  const Vec3f wo = frame.toWorld(sphericalDir(0.9, 0.4));
  for (int k = 0; k < 200; ++k) {
    const float uLobe = u(rng);
    const Vec2f uv{u(rng), u(rng)};
    const auto sg = g.sample(wo, uLobe, uv);
    const auto sb = b.sample(frame.toLocal(wo), uLobe, uv);
    ASSERT_EQ(sg.has_value(), sb.has_value());
    if (!sg) continue;
    EXPECT_EQ(sg->pdf, sb->pdf);
    EXPECT_EQ(sg->f, sb->f);
    EXPECT_NEAR(dot(sg->wi, frame.toWorld(sb->wi)), 1.0f, 1e-6f);
  }
}

TEST(GltfBsdf, LayeredReflectionIsReciprocal) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  const Frame frame = Frame::fromNormal({0, 0, 1});
  for (const GltfBsdfParams& p : {layered(1, 0.8f, 0, 0, false), layered(0.5f, 0.5f, 0, 0.5f, false)}) {
    const GltfBsdf g(p, frame, tiltedCoat());
    for (int k = 0; k < 100; ++k) {
      const Vec3f a = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Vec3f b = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Spectrum f1 = g.eval(a, b), f2 = g.eval(b, a);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f1[c], f2[c], 1e-4f * std::max(1.0f, f1[c]));
    }
  }
}

// White layers over a white base: no direction returns more than arrives
// (reflected plus refracted flux, thin-walled so that radiance is flux).
TEST(GltfBsdf, WhiteLayeredMaterialHasAlbedoAtMostOne) {
  const Frame frame = Frame::fromNormal({0, 0, 1});
  for (const float transmission : {0.0f, 0.5f, 1.0f})
    for (const double t : {0.0, 45.0, 80.0}) {
      GltfBsdfParams p = layered(1, 1, transmission, 0, true);
      p.base.baseColor = p.dielectric.tint = Spectrum(1.0f);
      p.sheenColor = Spectrum(Rgb{1, 1, 1});
      const GltfBsdf g(p, frame, frame);
      const Vec3f wo = sphericalDir(t * kPi / 180, 0.0);
      const double albedo = integrateSphere(
          [&](const Vec3f& wi) { return g.eval(wo, wi)[1] * std::abs(wi.z); }, 0, kPi, 0, 2 * kPi, 400);
      // (The base's 32x32 albedo table is coarsest at grazing angles.)
      EXPECT_LE(albedo, 1.0 + (t > 70 ? 1e-2 : 5e-3)) << "transmission " << transmission << " theta " << t;
      EXPECT_GT(albedo, 0.6) << "transmission " << transmission << " theta " << t;
    }
}

TEST(GltfBsdf, SamplingMatchesPdfChiSquare) {
  struct Case {
    GltfBsdfParams p;
    double thetaDeg;
  };
  const std::vector<Case> cases = {
      {layered(1, 0, 0, 0, false), 30},
      {layered(0, 1, 0, 0, false), 60},
      {layered(0, 0, 1, 0, false), 20},
      {layered(0.7f, 0.5f, 0.6f, 0.3f, false), 45},
      {layered(0.7f, 0.5f, 0.6f, 0.3f, true), 70},
  };
  const double significance = 0.01 / double(cases.size());
  const Frame frame = Frame::fromNormal({0, 0, 1});
  for (const Case& c : cases) {
    const GltfBsdf g(c.p, frame, tiltedCoat());
    const Vec3f wo = sphericalDir(c.thetaDeg * kPi / 180, 0.5);
    std::uniform_real_distribution<float> u(0, 1);
    const test::ChiSquareResult r = test::sphereChiSquare(
        [&](std::mt19937& rng) -> std::optional<Vec3f> {
          const float a = u(rng), b1 = u(rng), b2 = u(rng);
          const auto s = g.sample(wo, a, {b1, b2});
          if (!s) return std::nullopt;
          return s->wi;
        },
        [&](const Vec3f& wi) { return double(g.pdf(wo, wi)); }, 200000);
    EXPECT_LE(r.pdfMass, 1.0 + 2e-3);
    EXPECT_LT(r.unexpected, 20);
    EXPECT_GT(r.pValue, significance)
        << "theta " << c.thetaDeg << " clearcoat " << c.p.clearcoat << " transmission " << c.p.transmission
        << ": chi2 " << r.chi2 << " dof " << r.dof;
  }
}

TEST(GltfBsdf, SampleReportsTheValuesOfEvalAndPdf) {
  const Frame frame = Frame::fromNormal(normalize(Vec3f{0.1f, 0.2f, 1}));
  const GltfBsdf g(layered(0.7f, 0.5f, 0.6f, 0.3f, false), frame, tiltedCoat());
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0, 1);
  const Vec3f wo = frame.toWorld(sphericalDir(0.7, 0.1));
  int transmitted = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto s = g.sample(wo, u(rng), {u(rng), u(rng)});
    if (!s) continue;
    transmitted += dot(s->wi, frame.n) < 0;
    EXPECT_NEAR(s->pdf, g.pdf(wo, s->wi), 1e-3f * s->pdf);
    EXPECT_NEAR(s->f[0], g.eval(wo, s->wi)[0], 1e-3f * std::max(1e-3f, s->f[0]));
  }
  EXPECT_GT(transmitted, 100);
}

// The renderer prepares each hit's BSDF for its view direction; that must be a
// pure saving: the same bits as the unprepared BSDF for that wo, and any other
// wo still evaluated as before. Every combination of layers, smooth to rough,
// specular layer on and off, random directions on both sides.
TEST(GltfBsdf, PreparedForAViewGivesTheSameBits) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(0, 1);
  const auto direction = [&] { return test::randomSphereDir(rng); };
  const auto same = [](const Spectrum& a, const Spectrum& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int samples = 0;
  for (int layers = 0; layers < 16; ++layers) {
    for (int k = 0; k < 200; ++k) {
      GltfBsdfParams p = layered(layers & 1 ? 0.7f : 0, layers & 2 ? 0.5f : 0, layers & 4 ? 0.6f : 0,
                                 u(rng) < 0.3f ? 1.0f : u(rng), layers & 8);
      p.base.roughness = u(rng) < 0.2f ? 0.0f : u(rng);
      p.base.specularWeight = u(rng) < 0.3f ? 0.0f : u(rng);
      p.clearcoatRoughness = u(rng);
      const Frame frame = Frame::fromNormal(normalize(Vec3f{0.1f, 0.2f, 1}));
      const Vec3f wo = direction(), wi = direction(), other = direction();
      const GltfBsdf plain(p, frame, tiltedCoat()), prepared(p, frame, tiltedCoat(), wo);
      for (const Vec3f& w : {wo, other}) {
        ASSERT_TRUE(same(plain.eval(w, wi), prepared.eval(w, wi))) << "layers " << layers << " k " << k;
        ASSERT_TRUE(same(plain.eval(wi, w), prepared.eval(wi, w))) << "layers " << layers << " k " << k;
        const float a = plain.pdf(w, wi), b = prepared.pdf(w, wi);
        ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "layers " << layers << " k " << k;
        // evalPdf is eval and pdf together, bit for bit, prepared or not.
        for (const GltfBsdf* g : {&plain, &prepared}) {
          const BsdfValue v = g->evalPdf(w, wi);
          ASSERT_TRUE(same(v.f, plain.eval(w, wi))) << "layers " << layers << " k " << k;
          ASSERT_EQ(std::memcmp(&v.pdf, &a, sizeof a), 0) << "layers " << layers << " k " << k;
        }
        const float uLobe = u(rng);
        const Vec2f uDir{u(rng), u(rng)};
        const auto sa = plain.sample(w, uLobe, uDir), sb = prepared.sample(w, uLobe, uDir);
        ASSERT_EQ(sa.has_value(), sb.has_value());
        if (!sa) continue;
        ++samples;
        ASSERT_EQ(sa->wi, sb->wi);
        ASSERT_TRUE(same(sa->f, sb->f));
        ASSERT_EQ(std::memcmp(&sa->pdf, &sb->pdf, sizeof sa->pdf), 0);
      }
    }
  }
  EXPECT_GT(samples, 2000);
}

}  // namespace
}  // namespace lensrt
