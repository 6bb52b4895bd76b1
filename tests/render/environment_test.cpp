#include "render/environment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/constants.h"
#include "render/distribution.h"

namespace lensrt {
namespace {

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
  // Midpoint rule on a grid that refines the texels: exact for a piecewise-constant density.
  constexpr int kNu = 32 * 8, kNv = 16 * 8;
  double integral = 0;
  for (int j = 0; j < kNv; ++j) {
    const double theta0 = kPi * j / kNv, theta1 = kPi * (j + 1) / kNv;
    const double solidAnglePerCell = (std::cos(theta0) - std::cos(theta1)) * 2 * kPi / kNu;
    for (int i = 0; i < kNu; ++i)
      integral +=
          env.pdf(Environment::uvToDirection({(i + 0.5f) / kNu, (j + 0.5f) / kNv})) * solidAnglePerCell;
  }
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
