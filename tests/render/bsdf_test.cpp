// The BRDF against closed forms: microfacet normalisation, reciprocity, energy
// bounds, and a chi-square test of the sampling routine against pdf().
#include "render/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

#include "bsdf_check_util.h"
#include "core/constants.h"

namespace lensrt {
namespace {

using test::sphericalDir;
// Over (theta, phi) regions of the hemisphere: test::integrateSphere.
const auto& integrateHemisphere = test::integrateSphere;

struct Case {
  float roughness, metallic, thetaDeg;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  for (float r : {0.5f, 0.75f, 1.0f})
    for (float m : {0.0f, 0.5f, 1.0f})
      for (float t : {10.0f, 45.0f, 75.0f}) c.push_back({r, m, t});
  return c;
}

BsdfParams paramsFor(const Case& c) {
  BsdfParams p;
  p.baseColor = Spectrum(Rgb{0.8f, 0.5f, 0.3f});
  p.metallic = c.metallic;
  p.roughness = c.roughness;
  return p;
}

TEST(Bsdf, GgxDistributionIsNormalised) {
  // Projected microfacet area equals the macro surface: int D(h) cos(theta_h) dh = 1.
  for (float r : {0.3f, 0.6f, 1.0f}) {
    BsdfParams p;
    p.roughness = r;
    const Bsdf b(p);
    const double i =
        integrateHemisphere([&](const Vec3f& h) { return b.ggxD(h) * h.z; }, 0, kPi / 2, 0, 2 * kPi, 400);
    EXPECT_NEAR(i, 1.0, 2e-3) << "roughness " << r;
    // Visible normals integrate to one too: int G1(wo) max(0, wo.h) D(h) / wo.z dh = 1.
    const Vec3f wo = sphericalDir(1.0, 0.3);
    const double g1 = 1.0 / (1.0 + b.smithLambda(wo));
    const double v = integrateHemisphere(
        [&](const Vec3f& h) { return g1 * std::max(0.0f, dot(wo, h)) * b.ggxD(h) / wo.z; }, 0, kPi / 2, 0,
        2 * kPi, 400);
    EXPECT_NEAR(v, 1.0, 2e-3) << "roughness " << r;
  }
}

TEST(Bsdf, PureLambertianIsBaseColourOverPi) {
  BsdfParams p;
  p.baseColor = Spectrum(Rgb{0.2f, 0.5f, 0.9f});
  p.metallic = 0;
  p.specularWeight = 0;
  const Bsdf b(p);
  const Spectrum f = b.eval(sphericalDir(0.3, 0.1), sphericalDir(1.2, 2.0));
  EXPECT_NEAR(f[0], 0.2 / kPi, 1e-6);
  EXPECT_NEAR(f[2], 0.9 / kPi, 1e-6);
  EXPECT_EQ(b.eval(sphericalDir(0.3, 0.1), {0, 0, -1}), Spectrum(0.0f));  // reflection only
}

TEST(Bsdf, IsReciprocal) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  for (const Case& c : cases()) {
    const Bsdf b(paramsFor(c));
    for (int k = 0; k < 50; ++k) {
      const Vec3f a = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Vec3f w = sphericalDir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Spectrum f1 = b.eval(a, w), f2 = b.eval(w, a);
      for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(f1[ch], f2[ch], 1e-5f * std::max(1.0f, f1[ch]));
    }
  }
}

TEST(Bsdf, DirectionalAlbedoIsAtMostOne) {
  // White base colour is the most reflective case for every metallic value.
  for (float r : {0.3f, 0.6f, 1.0f})
    for (float m : {0.0f, 0.5f, 1.0f})
      for (float t : {0.0f, 30.0f, 60.0f, 85.0f}) {
        BsdfParams p;
        p.baseColor = Spectrum(Rgb{1, 1, 1});
        p.metallic = m;
        p.roughness = r;
        const Bsdf b(p);
        const Vec3f wo = sphericalDir(t * kPi / 180, 0.0);
        const double albedo = integrateHemisphere([&](const Vec3f& wi) { return b.eval(wo, wi)[1] * wi.z; },
                                                  0, kPi / 2, 0, 2 * kPi, 300);
        EXPECT_LE(albedo, 1.0 + 2e-3) << "r " << r << " m " << m << " theta " << t;
        // A white dielectric loses nothing: what the specular layer does not
        // reflect, the white diffuse under it does (E + (1 - E) = 1).
        // (Looser at grazing, where the 32x32 albedo table is coarsest.)
        if (m == 0) {
          EXPECT_NEAR(albedo, 1.0, t > 80 ? 0.03 : 0.01) << "r " << r << " theta " << t;
        }
        EXPECT_GT(albedo, 0.2) << "r " << r << " m " << m << " theta " << t;
      }
}

TEST(Bsdf, SampleReportsTheValuesOfEvalAndPdf) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  for (const Case& c : cases()) {
    const Bsdf b(paramsFor(c));
    const Vec3f wo = sphericalDir(c.thetaDeg * kPi / 180, 0.7);
    for (int k = 0; k < 200; ++k) {
      const auto s = b.sample(wo, u(rng), {u(rng), u(rng)});
      if (!s) continue;
      EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), 1e-4f * s->pdf);
      EXPECT_NEAR(s->f[1], b.eval(wo, s->wi)[1], 1e-4f * s->f[1]);
    }
  }
}

// evalPdf shares the half vector and D between the value and the density:
// the same bits as eval and pdf, smooth to rough, metal to dielectric, with
// and without the prepared view, directions on both sides.
TEST(Bsdf, EvalPdfIsEvalAndPdfBitForBit) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  const auto direction = [&] { return test::randomSphereDir(rng); };
  for (int k = 0; k < 4000; ++k) {
    BsdfParams p;
    p.baseColor = Spectrum(Rgb{u(rng), u(rng), u(rng)});
    p.metallic = k % 5 == 0 ? 1.0f : u(rng);
    p.roughness = k % 7 == 0 ? 0.0f : u(rng);
    p.specularWeight = k % 3 == 0 ? 0.0f : u(rng);
    const Vec3f wo = direction(), wi = k % 11 == 0 ? Vec3f{-wo.x, -wo.y, wo.z} : direction();
    for (const Bsdf& b : {Bsdf(p), Bsdf(p, wo.z)}) {
      const BsdfValue v = b.evalPdf(wo, wi);
      const Spectrum f = b.eval(wo, wi);
      const float pdf = b.pdf(wo, wi);
      ASSERT_EQ(std::memcmp(&v.f, &f, sizeof f), 0) << k;
      ASSERT_EQ(std::memcmp(&v.pdf, &pdf, sizeof pdf), 0) << k;
    }
  }
}

using test::chiSquarePValue;

TEST(Bsdf, SamplingMatchesPdfChiSquare) {
  constexpr int kThetaBins = 16, kPhiBins = 32, kSamples = 100000;
  const std::vector<Case> all = cases();
  const double significance = 0.01 / double(all.size());  // Sidak-style correction
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  for (const Case& c : all) {
    const Bsdf b(paramsFor(c));
    const Vec3f wo = sphericalDir(c.thetaDeg * kPi / 180, 0.0);
    std::vector<double> observed(kThetaBins * kPhiBins + 1, 0), expected(kThetaBins * kPhiBins + 1, 0);
    int valid = 0;
    for (int k = 0; k < kSamples; ++k) {
      const auto s = b.sample(wo, u(rng), {u(rng), u(rng)});
      if (!s) continue;
      ++valid;
      const double theta = std::acos(std::clamp(double(s->wi.z), -1.0, 1.0));
      double phi = std::atan2(s->wi.y, s->wi.x);
      if (phi < 0) phi += 2 * kPi;
      const int ti = std::min(kThetaBins - 1, int(theta / (kPi / 2) * kThetaBins));
      const int pi = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
      observed[ti * kPhiBins + pi] += 1;
    }
    observed.back() = kSamples - valid;  // rejected samples: the pdf's missing mass
    double total = 0;
    for (int ti = 0; ti < kThetaBins; ++ti)
      for (int pi = 0; pi < kPhiBins; ++pi) {
        const double mass = integrateHemisphere([&](const Vec3f& wi) { return b.pdf(wo, wi); },
                                                ti * kPi / 2 / kThetaBins, (ti + 1) * kPi / 2 / kThetaBins,
                                                pi * 2 * kPi / kPhiBins, (pi + 1) * 2 * kPi / kPhiBins, 8);
        expected[ti * kPhiBins + pi] = mass * kSamples;
        total += mass;
      }
    ASSERT_LE(total, 1.0 + 1e-3);
    expected.back() = std::max(0.0, 1.0 - total) * kSamples;
    // Pool bins too small for the chi-square approximation.
    double chi2 = 0, pooledObs = 0, pooledExp = 0;
    int dof = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
      if (expected[i] < 5) {
        pooledObs += observed[i];
        pooledExp += expected[i];
        continue;
      }
      chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
      ++dof;
    }
    if (pooledExp >= 5) {
      chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
      ++dof;
    } else {
      EXPECT_LT(pooledObs, 20) << "samples where the pdf says there are none";
    }
    const double p = chiSquarePValue(chi2, dof - 1);
    EXPECT_GT(p, significance) << "roughness " << c.roughness << " metallic " << c.metallic << " theta "
                               << c.thetaDeg << ": chi2 " << chi2 << " dof " << dof - 1;
  }
}

}  // namespace
}  // namespace lensrt
