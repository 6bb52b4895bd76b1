#include "render/environment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/constants.h"
#include "render/distribution.h"

namespace lensrt {
namespace {

// The integral of a density over the sphere by the midpoint rule on a grid
// that refines the test map's 32 x 16 texels: exact for a piecewise-constant
// density.
template <class Density>
double sphereIntegral(const Density& density) {
  constexpr int kNu = 32 * 8, kNv = 16 * 8;
  double integral = 0;
  for (int j = 0; j < kNv; ++j) {
    const double theta0 = kPi * j / kNv, theta1 = kPi * (j + 1) / kNv;
    const double cell = (std::cos(theta0) - std::cos(theta1)) * 2 * kPi / kNu;
    for (int i = 0; i < kNu; ++i)
      integral += density(Environment::uvToDirection({(i + 0.5f) / kNu, (j + 0.5f) / kNv})) * cell;
  }
  return integral;
}

// A lat-long map with a bright small "sun", a sky gradient and a dark band.
Image testMap() {
  Image img(32, 16, {"R", "G", "B"});
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float v = 0.2f + 0.8f * float(img.height - y) / float(img.height);
      if (y == 12) v = 0;
      if (x == 20 && y == 4) v = 200;
      img.at(x, y, 0) = v;
      img.at(x, y, 1) = 0.5f * v;
      img.at(x, y, 2) = 0.25f * v + 0.01f;
    }
  return img;
}

TEST(Environment, LatLongAxes) {
  const auto near = [](Vec3f a, Vec3f b) { return length(a - b) < 1e-5f; };
  EXPECT_TRUE(near(Environment::uvToDirection({0.5f, 0.5f}), {0, 0, -1}));
  EXPECT_TRUE(near(Environment::uvToDirection({0.75f, 0.5f}), {1, 0, 0}));
  EXPECT_TRUE(near(Environment::uvToDirection({0.3f, 0.0f}), {0, 1, 0}));
  for (const Vec2f uv : {Vec2f{0.1f, 0.2f}, Vec2f{0.6f, 0.9f}, Vec2f{0.95f, 0.5f}}) {
    const Vec2f back = Environment::directionToUv(Environment::uvToDirection(uv));
    EXPECT_NEAR(back.x, uv.x, 1e-5f);
    EXPECT_NEAR(back.y, uv.y, 1e-5f);
  }
}

TEST(Environment, ImportancePdfIntegratesToOneOverTheSphere) {
  const Environment env = Environment::latLong(testMap());
  const double integral = sphereIntegral([&](const Vec3f& d) { return env.pdf(d); });
  // The density uses each row's centre sin(theta) while the cell uses the exact
  // band: the mismatch is second order in the texel height.
  EXPECT_NEAR(integral, 1.0, 5e-3);
}

TEST(Environment, ImportanceSamplingEstimatesTheIncidentPower) {
  const Image map = testMap();
  const Environment env = Environment::latLong(map);
  // Closed form: each texel is constant over a band of solid angle dphi (cos t0 - cos t1).
  double exact = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      exact += map.at(x, y, 0) * (2 * kPi / map.width) *
               (std::cos(kPi * y / map.height) - std::cos(kPi * (y + 1) / map.height));
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0, 1);
  double sum = 0;
  constexpr int kN = 200000;
  for (int k = 0; k < kN; ++k) {
    const auto s = env.sample({u(rng), u(rng)});
    if (!s) continue;  // landed exactly on a black texel's edge: contributes zero
    sum += s->radiance.x / s->pdf;
  }
  EXPECT_NEAR(sum / kN, exact, 0.01 * exact);
}

TEST(Environment, ConstantAndBlack) {
  const Environment c = Environment::constant({1, 2, 3});
  EXPECT_EQ(c.eval({0, 1, 0}), Rgb(1, 2, 3));
  EXPECT_NEAR(c.pdf({0, 0, 1}), 1 / (4 * kPi), 1e-7);
  EXPECT_TRUE(Environment().isBlack());
  EXPECT_FALSE(Environment().sample({0.5f, 0.5f}).has_value());
}

// The rotation the README documents, written out independently of the
// renderer: R_y(a) by the right-hand rule.
Vec3f rotateY(const Vec3f& d, double degrees) {
  const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
  return {float(c * d.x + s * d.z), d.y, float(-s * d.x + c * d.z)};
}

// Direction at the centre of texel (x, y) of a W x H map.
Vec3f texelCentre(int x, int y, int w, int h) {
  return Environment::uvToDirection({(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)});
}

TEST(Environment, RotatedMapIsTheMapLookedUpAtTheRotatedDirection) {
  const Image map = testMap();
  const Environment base = Environment::latLong(map);
  // +90 degrees: what the unrotated map shows straight ahead (-Z) moves to the left (-X).
  const Vec3f left = rotateY({0, 0, -1}, 90);
  EXPECT_NEAR(left.x, -1, 1e-6);
  EXPECT_NEAR(left.z, 0, 1e-6);
  for (const double degrees : {33.0, -100.0, 200.0}) {
    SCOPED_TRACE(degrees);
    const Environment rotated = base.rotatedAboutY(float(degrees));
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < map.width; ++x) {
        const Vec3f d = texelCentre(x, y, map.width, map.height);
        ASSERT_EQ(rotated.eval(rotateY(d, degrees)), base.eval(d)) << x << "," << y;
        ASSERT_NEAR(rotated.pdf(rotateY(d, degrees)), base.pdf(d), 1e-4f * base.pdf(d)) << x << "," << y;
      }
    // Turns compose: turning back restores the map.
    const Vec3f sun = texelCentre(20, 4, map.width, map.height);
    EXPECT_EQ(rotated.rotatedAboutY(float(-degrees)).eval(sun), base.eval(sun));
  }
  // Sampled directions carry the radiance and density the lookups give them.
  const Environment rotated = base.rotatedAboutY(33);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const auto s = rotated.sample({u(rng), u(rng)});
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->radiance, rotated.eval(s->direction));
    EXPECT_FLOAT_EQ(s->pdf, rotated.pdf(s->direction));
  }
}

TEST(Environment, IntensityScalesTheRadianceNotTheSampling) {
  const Environment base = Environment::latLong(testMap());
  const Environment twice = base.scaled(2);
  const Vec3f d = texelCentre(20, 4, 32, 16);
  EXPECT_EQ(twice.eval(d), base.eval(d) * 2.0f);
  EXPECT_EQ(twice.pdf(d), base.pdf(d));
  EXPECT_FLOAT_EQ(twice.averageLuminance(), 2 * base.averageLuminance());
  EXPECT_TRUE(base.scaled(0).isBlack());
  EXPECT_EQ(Environment::constant({1, 2, 3}).scaled(0.5f).eval({0, 1, 0}), Rgb(0.5f, 1, 1.5f));
  EXPECT_THROW(base.scaled(-1), std::invalid_argument);
}

// Chi-square of the map's sampling against pdf(), unrotated and rotated. The
// bins are the texels as they lie in the world after the rotation the README
// documents (computed here, not by Environment), so the expected mass of each
// is exactly pdf x sin(theta) x its (phi, theta) area: pdf() is p(u, v) /
// (2 pi^2 sin(theta)), constant over a texel in (phi, theta).
TEST(Environment, MapSamplingMatchesItsPdfChiSquare) {
  const Image map = testMap();
  const int w = map.width, h = map.height;
  constexpr int kSamples = 200000;
  for (const double degrees : {0.0, 33.0, -100.0}) {
    SCOPED_TRACE(degrees);
    const Environment env = Environment::latLong(map).rotatedAboutY(float(degrees));
    std::vector<double> observed(std::size_t(w) * h, 0.0), expected(observed.size(), 0.0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0, 1);
    for (int k = 0; k < kSamples; ++k) {
      const auto s = env.sample({u(rng), u(rng)});
      ASSERT_TRUE(s.has_value());
      const Vec3f m = rotateY(s->direction, -degrees);  // back to the map's frame
      const Vec2f uv = Environment::directionToUv(m);
      const int x = std::min(w - 1, int(uv.x * float(w))), y = std::min(h - 1, int(uv.y * float(h)));
      observed[std::size_t(y) * w + x] += 1;
    }
    double total = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double theta = kPi * (y + 0.5) / h;
        const double mass =
            env.pdf(rotateY(texelCentre(x, y, w, h), degrees)) * std::sin(theta) * (2 * kPi / w) * (kPi / h);
        expected[std::size_t(y) * w + x] = mass * kSamples;
        total += mass;
      }
    EXPECT_NEAR(total, 1.0, 1e-4);
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
      EXPECT_LT(pooledObs, 10) << "samples where the pdf says there are none";
    }
    ASSERT_GT(dof, 100);
    // Wilson-Hilferty upper tail at 1e-3.
    const int k = dof - 1;
    const double z = (std::cbrt(chi2 / k) - (1 - 2.0 / (9 * k))) / std::sqrt(2.0 / (9 * k));
    EXPECT_GT(0.5 * std::erfc(z / std::sqrt(2.0)), 1e-3) << "chi2 " << chi2 << " dof " << k;
  }
}

// A diffuse plane (normal +Y, albedo 1) under a dim sky with a small bright sun
// in the map: the reflected radiance L_o = E / pi, estimated (a) from the map's
// importance samples, (b) from uniform sphere samples, (c) by MIS of (a) with
// cosine-weighted BSDF samples (power heuristic), as the integrator combines
// them. All three agree with the closed form; (a) and (c) have at least 10x
// less variance than (b).
TEST(Environment, ImportanceSamplingASunInTheMapCutsVarianceTenfold) {
  Image map(64, 32, {"R", "G", "B"});
  for (float& v : map.pixels) v = 0.5f;
  const int sunX = 40, sunY = 5;  // about 30 degrees from the zenith
  for (int c = 0; c < 3; ++c) map.at(sunX, sunY, c) = 5000.0f;
  for (const double degrees : {0.0, 70.0}) {
    SCOPED_TRACE(degrees);
    const Environment env = Environment::latLong(map).rotatedAboutY(float(degrees));
    // Closed form: each texel row is a band; integral of cos(theta) over it is
    // dphi (sin^2 t1 - sin^2 t0) / 2 on the upper hemisphere (rotation about
    // +Y keeps every row's elevation).
    double exact = 0;
    for (int y = 0; y < map.height / 2; ++y)
      for (int x = 0; x < map.width; ++x) {
        const double t0 = kPi * y / map.height, t1 = kPi * (y + 1) / map.height;
        exact += map.at(x, y, 0) * (2 * kPi / map.width) *
                 (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / 2;
      }
    exact /= kPi;

    constexpr int kN = 20000;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    const auto stats = [&](auto estimate) {
      double sum = 0, sum2 = 0;
      for (int k = 0; k < kN; ++k) {
        const double f = estimate();
        sum += f;
        sum2 += f * f;
      }
      const double mean = sum / kN;
      return std::pair{mean, (sum2 / kN - mean * mean)};
    };
    const auto importance = stats([&] {
      const auto s = env.sample({u(rng), u(rng)});
      if (!s) return 0.0;
      return double(s->radiance.x) * std::max(0.0f, s->direction.y) / kPi / s->pdf;
    });
    const auto uniform = stats([&] {
      const float z = 1 - 2 * u(rng), r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPiF * u(rng);
      const Vec3f d{r * std::cos(phi), z, r * std::sin(phi)};
      return double(env.eval(d).x) * std::max(0.0f, d.y) / kPi * (4 * kPi);
    });
    const auto mis = stats([&] {
      double f = 0;
      if (const auto s = env.sample({u(rng), u(rng)}); s && s->direction.y > 0) {
        const float bsdfPdf = s->direction.y / kPiF;
        const double wl = double(s->pdf) * s->pdf / (double(s->pdf) * s->pdf + double(bsdfPdf) * bsdfPdf);
        f += wl * s->radiance.x * s->direction.y / kPi / s->pdf;
      }
      // Cosine-weighted direction about +Y.
      const float r = std::sqrt(u(rng)), phi = 2 * kPiF * u(rng);
      const Vec3f d{r * std::cos(phi), std::sqrt(std::max(0.0f, 1 - r * r)), r * std::sin(phi)};
      const float bsdfPdf = d.y / kPiF;
      if (bsdfPdf > 0) {
        const float lightPdf = env.pdf(d);
        const double wb =
            double(bsdfPdf) * bsdfPdf / (double(bsdfPdf) * bsdfPdf + double(lightPdf) * lightPdf);
        f += wb * env.eval(d).x * d.y / kPi / bsdfPdf;
      }
      return f;
    });
    for (const auto& [mean, variance] : {importance, uniform, mis})
      EXPECT_NEAR(mean, exact, 4 * std::sqrt(variance / kN) + 1e-3 * exact);
    EXPECT_GT(uniform.second, 10 * importance.second)
        << "variance: importance " << importance.second << ", uniform " << uniform.second;
    EXPECT_GT(uniform.second, 10 * mis.second)
        << "variance: MIS " << mis.second << ", uniform " << uniform.second;
  }
}

// The sun that lens flare's light pass takes (Environment::hasSun): the test
// map's one bright texel (the sky is under 1% of it), and none where the
// brightest part is wide or the map constant. Its density integrates to 1
// over the sphere, and its samples estimate the texel's radiance times its
// solid angle (closed form: 2 pi / 32 x (cos(4 pi / 16) - cos(5 pi / 16))).
TEST(Environment, TheSunIsTheSmallBrightestPartOfTheMap) {
  const Environment env = Environment::latLong(testMap());
  ASSERT_TRUE(env.hasSun());
  const Vec3f centre = Environment::uvToDirection({20.5f / 32, 4.5f / 16});
  EXPECT_TRUE(env.inSun(centre));
  EXPECT_FALSE(env.inSun(Environment::uvToDirection({10.5f / 32, 4.5f / 16})));
  const double integral = sphereIntegral([&](const Vec3f& d) { return env.pdfSun(d); });
  EXPECT_NEAR(integral, 1.0, 5e-3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  double sum = 0;
  constexpr int kN = 20000;
  for (int k = 0; k < kN; ++k) {
    const std::optional<EnvironmentSample> s = env.sampleSun({u(rng), u(rng)});
    ASSERT_TRUE(s);
    ASSERT_TRUE(env.inSun(s->direction));
    sum += s->radiance.x / s->pdf;
  }
  const double solidAngle = 2 * kPi / 32 * (std::cos(4 * kPi / 16) - std::cos(5 * kPi / 16));
  EXPECT_NEAR(sum / kN / (200.0 * solidAngle), 1.0, 0.01);
  // Turned with the map, gone with its light.
  EXPECT_TRUE(env.rotatedAboutY(90).inSun(Vec3f{centre.z, centre.y, -centre.x}));  // -Z turns to -X
  EXPECT_FALSE(env.rotatedAboutY(90).inSun(centre));
  EXPECT_FALSE(env.scaled(0).hasSun());
  EXPECT_FALSE(Environment::constant({1, 1, 1}).hasSun());
  // A bright band 4 rows deep (over 0.05 sr) is no sun, nor a uniform map.
  Image wide(32, 16, {"R", "G", "B"});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) wide.at(x, y, c) = 100;
  EXPECT_FALSE(Environment::latLong(wide).hasSun());
  Image uniform(32, 16, {"R", "G", "B"});
  for (float& v : uniform.pixels) v = 1;
  EXPECT_FALSE(Environment::latLong(uniform).hasSun());
}

TEST(Distribution1D, PicksInProportionAndNeverPicksZeroWeights) {
  const Distribution1D d({1, 0, 3, 0});
  EXPECT_FLOAT_EQ(d.probability(0), 0.25f);
  EXPECT_FLOAT_EQ(d.probability(2), 0.75f);
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < 1000; ++i) ++counts[d.sample((i + 0.5f) / 1000)];
  EXPECT_EQ(counts[0], 250);
  EXPECT_EQ(counts[2], 750);
  EXPECT_EQ(counts[1] + counts[3], 0);
  EXPECT_EQ(d.sample(std::nextafter(1.0f, 0.0f)), 2u);
}

}  // namespace
}  // namespace lensrt
