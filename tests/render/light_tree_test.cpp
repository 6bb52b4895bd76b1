// The light tree (render/light_tree.h) and LightSet's tree sampling: the
// picks follow the pmf (chi-square), the pmf sums to 1 and equals what
// sample() reports (MIS needs both), irradiance from many lights matches its
// closed form, and a furnace room of many emitters renders its closed form
// with tree and power picks alike.
#include "render/light_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/bsdf_check_util.h"
#include "render/lights.h"
#include "render/test_scene_util.h"

namespace lensrt {
namespace {

Vec3f randomUnit(std::mt19937& rng) {
  return test::randomSphereDir(rng);
}

// Point lights, spots and small oriented emitters (some two-sided) spread
// over a 20 x 20 m street, 1 to 4 m up.
std::vector<LightBounds> streetLights(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<LightBounds> lights;
  for (int i = 0; i < count; ++i) {
    LightBounds b;
    const Vec3f pos{20 * u(rng) - 10, 1 + 3 * u(rng), 20 * u(rng) - 10};
    b.phi = 0.1f + 10 * u(rng);
    switch (i % 3) {
      case 0:  // point
        b.bounds.extend(pos);
        b.cosThetaO = -1;
        break;
      case 1:  // spot looking down
        b.bounds.extend(pos);
        b.axis = normalize(Vec3f{u(rng) - 0.5f, -1, u(rng) - 0.5f});
        b.cosThetaO = std::cos(0.3f);
        b.cosThetaE = std::cos(0.4f);
        break;
      default: {  // a small triangle
        const Vec3f a = randomUnit(rng) * 0.2f, c = randomUnit(rng) * 0.2f;
        b.bounds.extend(pos);
        b.bounds.extend(pos + a);
        b.bounds.extend(pos + c);
        b.axis = normalize(cross(a, c));
        b.cosThetaO = 1;
        b.twoSided = i % 2 == 0;
      }
    }
    lights.push_back(b);
  }
  return lights;
}

// Point lights alone, seen from a point without a normal: every node can
// light it, so the walk never ends where both children are dark and the pmf
// adds up to 1.
TEST(LightTree, PmfSumsToOneWhenEveryLightCanReachThePoint) {
  std::vector<LightBounds> lights;
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 500; ++i) {
    LightBounds b;
    b.bounds.extend(Vec3f{20 * u(rng) - 10, 3 * u(rng), 20 * u(rng) - 10});
    b.phi = 0.1f + u(rng);
    b.cosThetaO = -1;
    lights.push_back(b);
  }
  const LightTree tree(lights);
  for (const Vec3f& p : {Vec3f{0, 0, 0}, Vec3f{9, 2, -3}, Vec3f{30, 1, 30}}) {
    double sum = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const float pmf = tree.pmf(p, {0, 0, 0}, i);
      EXPECT_GT(pmf, 0);
      sum += pmf;
    }
    EXPECT_NEAR(sum, 1.0, 1e-5);
  }
  // Injected bug (measured): pmf() reading the trail from its top bit
  // instead of the root's: sums of 0.38, 0.62 and 0.88.
}

// With normals and cones, a walk can reach a node whose children are both
// dark from p (their bounds are tighter than their parent's): sample()
// returns no light then, and the pmf adds up to less than 1. It never leaves
// out a light that can reach p, which is what keeps estimates unbiased.
TEST(LightTree, PmfIsPositiveForEveryLightThatCanReachThePointAndEqualsWhatSampleReports) {
  const std::vector<LightBounds> lights = streetLights(300, 7);
  const LightTree tree(lights);
  ASSERT_EQ(tree.nodeCount(), 2 * lights.size() - 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0, 1);
  int checked = 0;
  for (int k = 0; k < 20; ++k) {
    const Vec3f p{24 * u(rng) - 12, 2 * u(rng), 24 * u(rng) - 12};
    // A receiver with a normal, and without one (zero).
    const Vec3f n = k % 4 == 3 ? Vec3f{0, 0, 0} : randomUnit(rng);
    double sum = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const float pmf = tree.pmf(p, n, i);
      if (lights[i].importance(p, n) > 0) {
        EXPECT_GT(pmf, 0) << "point " << k << " light " << i;
      }
      sum += pmf;
    }
    ASSERT_LE(sum, 1 + 1e-5) << "point " << k;
    ASSERT_GT(sum, 0.5) << "point " << k;
    for (int s = 0; s < 500; ++s) {
      const std::optional<LightPick> pick = tree.sample(p, n, u(rng));
      if (!pick) continue;
      ASSERT_GT(pick->pmf, 0);
      // The same products in the same order: equal, not merely close.
      ASSERT_EQ(pick->pmf, tree.pmf(p, n, pick->light)) << "point " << k << " light " << pick->light;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20 * 500 * 9 / 10);
  // Injected bugs (measured): sample() reporting i1 / (i0 + i0) for the
  // second child instead of one minus the first's: 0.0866 against 0.0579 at
  // the first point; pmf() reading the trail from its top bit: the sum 8.1.
}

// The tree's walk weighs both children with importancePair (in SSE lanes on
// x86-64): the very bits of importance() on each, for every kind of bounds
// (points, cones, two-sided patches, boxes the point is inside), with and
// without a receiver's normal, and for a point at a light's centre.
TEST(LightTree, ImportancePairHasTheBitsOfImportance) {
  std::vector<LightBounds> lights = streetLights(300, 5);
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0, 1);
  // Large boxes as well, which many points are inside.
  for (int i = 0; i < 100; ++i) {
    LightBounds b = lights[std::size_t(i)];
    b.bounds.extend(Vec3f{20 * u(rng) - 10, 4 * u(rng), 20 * u(rng) - 10});
    b.cosThetaO = 2 * u(rng) - 1;
    b.cosThetaE = u(rng) < 0.5f ? 0.0f : std::cos(1.5f * u(rng));
    lights.push_back(b);
  }
  std::vector<ImportanceBounds> bounds;
  for (const LightBounds& b : lights) bounds.emplace_back(b);
  int lit = 0;
  for (int k = 0; k < 4000; ++k) {
    const ImportanceBounds& a = bounds[std::size_t(k) % bounds.size()];
    const ImportanceBounds& b = bounds[std::size_t(k * 7 + 3) % bounds.size()];
    const Vec3f p = k % 50 == 0 ? a.centre : Vec3f{24 * u(rng) - 12, 5 * u(rng) - 1, 24 * u(rng) - 12};
    const Vec3f n = k % 4 == 3 ? Vec3f{0, 0, 0} : randomUnit(rng);
    const std::array<float, 2> pair = importancePair(ImportancePair(a, b), p, n);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(pair[0]), std::bit_cast<std::uint32_t>(a.importance(p, n))) << k;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(pair[1]), std::bit_cast<std::uint32_t>(b.importance(p, n))) << k;
    lit += pair[0] > 0;
  }
  EXPECT_GT(lit, 1000);
  EXPECT_LT(lit, 3990);  // some dark: behind a cone, or beyond its emission
}

TEST(LightTree, LightsWithoutPowerAreNeverPicked) {
  std::vector<LightBounds> lights = streetLights(30, 3);
  lights[4].phi = 0;
  lights[9].phi = std::numeric_limits<float>::infinity();
  const LightTree tree(lights);
  const Vec3f p{0, 0, 0}, n{0, 1, 0};
  EXPECT_EQ(tree.pmf(p, n, 4), 0.0f);
  EXPECT_EQ(tree.pmf(p, n, 9), 0.0f);
  EXPECT_EQ(tree.pmf(p, n, 1000), 0.0f);
  for (int s = 0; s < 1000; ++s) {
    const std::optional<LightPick> pick = tree.sample(p, n, (s + 0.5f) / 1000);
    ASSERT_TRUE(pick);
    EXPECT_NE(pick->light, 4u);
    EXPECT_NE(pick->light, 9u);
  }
}

// Chi-square over the lights and "no light": counts of N picks against N
// pmf, `none` picks against N (1 - sum of the pmf).
double pickChiSquarePValue(const std::vector<long>& counts, long none, const std::vector<double>& pmf,
                           long n) {
  double chi2 = 0, pooledExpected = 0, pooledObserved = 0, sum = 0;
  int bins = 0;
  for (const double p : pmf) sum += p;
  const double noneExpected = std::max(0.0, 1 - sum) * double(n);
  if (noneExpected >= 5) {
    chi2 += (double(none) - noneExpected) * (double(none) - noneExpected) / noneExpected;
    ++bins;
  } else {
    pooledExpected += noneExpected;
    pooledObserved += double(none);
  }
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double expected = pmf[i] * double(n);
    if (expected < 5) {
      pooledExpected += expected;
      pooledObserved += double(counts[i]);
      continue;
    }
    chi2 += (double(counts[i]) - expected) * (double(counts[i]) - expected) / expected;
    ++bins;
  }
  if (pooledExpected > 0) {
    chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++bins;
  }
  return test::chiSquarePValue(chi2, bins - 1);
}

TEST(LightTree, PicksFollowThePmf) {
  const std::vector<LightBounds> lights = streetLights(200, 5);
  const LightTree tree(lights);
  constexpr long kSamples = 400000;
  const Vec3f points[] = {{0, 0, 0}, {8, 0.5f, -7}, {-11, 3, 2}};
  const Vec3f normals[] = {{0, 1, 0}, normalize(Vec3f{1, 1, 0}), {0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    std::vector<double> pmf(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) pmf[i] = tree.pmf(points[k], normals[k], i);
    std::vector<long> counts(lights.size(), 0);
    long none = 0;
    std::mt19937 rng(100 + k);
    std::uniform_real_distribution<float> u(0, 1);
    for (long s = 0; s < kSamples; ++s) {
      const std::optional<LightPick> pick = tree.sample(points[k], normals[k], u(rng));
      if (pick)
        ++counts[pick->light];
      else
        ++none;
    }
    const double p = pickChiSquarePValue(counts, none, pmf, kSamples);
    EXPECT_GT(p, 1e-3) << "point " << k;

    // The test can fail: a pmf 5% high for the first 100 lights (renormalised)
    // is refused at every point (measured p-values 1e-27, 8e-23, 1e-21, with
    // 0.22, 0.38, 0.37 for the right one). Injected bug (measured): sample()
    // stepping to the first child when u < 1.05 p0: p-value 0 at all three.
    std::vector<double> wrong = pmf;
    double total = 0;
    for (std::size_t i = 0; i < wrong.size(); ++i) total += wrong[i];
    double wrongTotal = 0;
    for (std::size_t i = 0; i < wrong.size(); ++i) wrongTotal += wrong[i] *= i < 100 ? 1.05 : 1.0;
    for (double& w : wrong) w *= total / wrongTotal;
    const double pWrong = pickChiSquarePValue(counts, none, wrong, kSamples);
    EXPECT_LT(pWrong, 1e-6) << "point " << k;
    std::printf("point %d: p %.3g, with the wrong pmf %.3g\n", k, p, pWrong);
  }
}

// Quads (two coplanar triangles each, one-sided) facing every way: each
// quad's pair shares a leaf, picked within it by power.
TEST(LightTree, AFlatPatchSharesALeafAndIsPickedWithinByPower) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<LightBounds> lights;
  for (int q = 0; q < 60; ++q) {
    const Vec3f c{20 * u(rng) - 10, 3 * u(rng), 20 * u(rng) - 10};
    const Vec3f a = randomUnit(rng) * 0.3f;
    const Vec3f normal = randomUnit(rng);
    const Vec3f b = normalize(cross(normal, a)) * (0.1f + 0.3f * u(rng));
    for (const auto& [p1, p2] : {std::pair{c + a, c + a + b}, std::pair{c + a + b, c + b}}) {
      LightBounds t;
      t.bounds.extend(c);
      t.bounds.extend(p1);
      t.bounds.extend(p2);
      t.axis = normal;
      t.cosThetaO = 1;
      t.phi = 0.5f + u(rng);
      lights.push_back(t);
    }
  }
  const LightTree tree(lights);
  EXPECT_EQ(tree.nodeCount(), 2 * 60 - 1);
  const Vec3f p{0.5f, 1, -0.5f}, n{0, 0, 0};
  for (std::size_t q = 0; q < 60; ++q) {
    const float a = tree.pmf(p, n, 2 * q), b = tree.pmf(p, n, 2 * q + 1);
    if (a > 0 || b > 0) {
      EXPECT_NEAR(a / (a + b), lights[2 * q].phi / (lights[2 * q].phi + lights[2 * q + 1].phi), 1e-5);
    }
  }
  constexpr long kSamples = 300000;
  std::vector<double> pmf(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) pmf[i] = tree.pmf(p, n, i);
  std::vector<long> counts(lights.size(), 0);
  long none = 0;
  for (long s = 0; s < kSamples; ++s) {
    const std::optional<LightPick> pick = tree.sample(p, n, u(rng));
    if (!pick) {
      ++none;
      continue;
    }
    ASSERT_EQ(pick->pmf, tree.pmf(p, n, pick->light));
    ++counts[pick->light];
  }
  EXPECT_GT(pickChiSquarePValue(counts, none, pmf, kSamples), 1e-3);
  // Injected bug (measured): the pick within a leaf at u^2 of its cdf
  // instead of u, while the pmf says by power: p-value 0.
}

// A small emitter of many triangles (a 5 cm ball of 300, facing every way)
// among 50 point lights over 20 m: its triangles share one leaf, picked
// within it by power, and sample() and pmf() still agree.
TEST(LightTree, ASmallEmitterOfManyTrianglesIsOneLeaf) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<LightBounds> lights;
  std::vector<std::int32_t> emitter;
  for (int i = 0; i < 50; ++i) {
    LightBounds b;
    b.bounds.extend(Vec3f{20 * u(rng) - 10, 3 * u(rng), 20 * u(rng) - 10});
    b.phi = 1;
    b.cosThetaO = -1;
    lights.push_back(b);
    emitter.push_back(-1);
  }
  const Vec3f ball{1, 2, -1};
  for (int t = 0; t < 300; ++t) {
    LightBounds b;
    const Vec3f normal = randomUnit(rng);
    b.bounds.extend(ball + normal * 0.05f);
    b.bounds.extend(ball + normal * 0.05f + randomUnit(rng) * 0.01f);
    b.axis = normal;
    b.phi = 0.01f + 0.02f * u(rng);
    lights.push_back(b);
    emitter.push_back(7);
  }
  const LightTree tree(lights, emitter);
  EXPECT_EQ(tree.nodeCount(), 2 * 51 - 1);
  const Vec3f p{0, 0, 0}, n{0, 1, 0};
  // Within the leaf by power: any two of its triangles that can be picked.
  const float a = tree.pmf(p, n, 50), b = tree.pmf(p, n, 51);
  ASSERT_GT(a, 0);
  EXPECT_NEAR(a / b, lights[50].phi / lights[51].phi, 1e-5);
  for (int s = 0; s < 20000; ++s) {
    const std::optional<LightPick> pick = tree.sample(p, n, u(rng));
    ASSERT_TRUE(pick);
    ASSERT_EQ(pick->pmf, tree.pmf(p, n, pick->light));
  }
}

// One quad light (a Cornell box's): one leaf, no walk, picked by power.
TEST(LightTree, OneQuadLightIsOneLeaf) {
  std::vector<LightBounds> lights(2);
  for (LightBounds& t : lights) {
    t.bounds.extend(Vec3f{0, 1, 0});
    t.axis = {0, -1, 0};
    t.cosThetaO = 1;
  }
  lights[0].bounds.extend(Vec3f{1, 1, 0});
  lights[0].bounds.extend(Vec3f{1, 1, 1});
  lights[0].phi = 1;
  lights[1].bounds.extend(Vec3f{0, 1, 1});
  lights[1].phi = 3;
  const LightTree tree(lights);
  EXPECT_EQ(tree.nodeCount(), 1u);
  EXPECT_FLOAT_EQ(tree.pmf({0.5f, 0, 0.5f}, {0, 1, 0}, 0), 0.25f);
  EXPECT_FLOAT_EQ(tree.pmf({0.5f, 0, 0.5f}, {0, 1, 0}, 1), 0.75f);
  EXPECT_EQ(tree.sample({0.5f, 0, 0.5f}, {0, 1, 0}, 0.2f)->light, 0u);
  EXPECT_EQ(tree.sample({0.5f, 0, 0.5f}, {0, 1, 0}, 0.3f)->light, 1u);
}

// --- LightSet over a scene of many lights -----------------------------------

// Irradiance at p (normal n) from a Lambertian triangle of radiance L seen
// from p entirely above its horizon (Lambert's formula for polygons).
double triangleIrradiance(const Vec3f& p, const Vec3f& n, const Vec3f v[3], double radiance) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3d a = Vec3d{v[i].x - p.x, v[i].y - p.y, v[i].z - p.z};
    const Vec3d b = Vec3d{v[(i + 1) % 3].x - p.x, v[(i + 1) % 3].y - p.y, v[(i + 1) % 3].z - p.z};
    const Vec3d ua = a / length(a), ub = b / length(b);
    const Vec3d g = cross(ua, ub);
    const double theta = std::acos(std::clamp(dot(ua, ub), -1.0, 1.0));
    sum += theta * dot(g / length(g), Vec3d{n.x, n.y, n.z});
  }
  return 0.5 * radiance * std::abs(sum);
}

struct ManyLights {
  SceneDesc scene;
  std::vector<std::array<Vec3f, 3>> triangles;  // world space, the mesh's order
  static constexpr float kRadiance = 3.0f;
};

// 60 point lights, 30 spots aiming down and 90 one-sided emissive triangles
// (side 0.15-0.45 m, facing any way: some turn their back on the receiver),
// 1 to 4 m above the plane y = 0 over 16 x 16 m.
ManyLights manyLights(std::uint32_t seed) {
  ManyLights m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  const auto above = [&] { return Vec3f{16 * u(rng) - 8, 1 + 3 * u(rng), 16 * u(rng) - 8}; };
  for (int i = 0; i < 90; ++i) {
    PunctualLight l;
    l.position = above();
    l.intensity = Rgb{1, 1, 1} * (0.2f + 2 * u(rng));
    if (i % 3 == 2) {
      l.type = PunctualLight::Type::Spot;
      l.direction = normalize(Vec3f{u(rng) - 0.5f, -1, u(rng) - 0.5f});
      l.innerConeAngle = 0.2f;
      l.outerConeAngle = 0.5f;
    }
    m.scene.lights.push_back(l);
  }
  Mesh mesh;
  mesh.material = 0;
  for (int t = 0; t < 90; ++t) {
    const Vec3f c = above();
    const float size = 0.15f + 0.3f * u(rng);
    const Vec3f a = randomUnit(rng) * size, b = randomUnit(rng) * size;
    const std::array<Vec3f, 3> tri{c, c + a, c + b};
    for (const Vec3f& v : tri) {
      mesh.indices.push_back(std::uint32_t(mesh.positions.size()));
      mesh.positions.push_back(v);
    }
    m.triangles.push_back(tri);
  }
  m.scene.meshes.push_back(mesh);
  Material emitter = test::whiteMatte();
  emitter.emissive = {ManyLights::kRadiance, ManyLights::kRadiance, ManyLights::kRadiance};
  m.scene.materials.push_back(emitter);
  m.scene.instances.push_back({0, Transform()});
  return m;
}

double exactIrradiance(const ManyLights& m, const Vec3f& p, const Vec3f& n) {
  double e = 0;
  for (const PunctualLight& l : m.scene.lights) {
    const Vec3f d = l.position - p;
    const float r2 = lengthSquared(d);
    const Vec3f wi = d / std::sqrt(r2);
    const double spot = l.type == PunctualLight::Type::Spot ? spotAttenuation(l, -wi) : 1.0;
    e += l.intensity.x * spot * std::max(0.0f, dot(wi, n)) / r2;
  }
  for (const auto& t : m.triangles) {
    const Vec3f normal = cross(t[1] - t[0], t[2] - t[0]);
    if (dot(p - t[0], normal) > 0) e += triangleIrradiance(p, n, t.data(), ManyLights::kRadiance);
  }
  return e;
}

struct Estimate {
  double mean = 0, standardError = 0;
};

Estimate estimateIrradiance(const LightSet& lights, const Vec3f& p, const Vec3f& n, int samples,
                            std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  double sum = 0, sum2 = 0;
  for (int s = 0; s < samples; ++s) {
    const float uPick = u(rng), u1 = u(rng), u2 = u(rng);
    const std::optional<LightSample> ls = lights.sample(p, n, uPick, {u1, u2});
    const double f = ls ? ls->radiance.x * std::max(0.0f, dot(ls->wi, n)) / ls->pdf : 0.0;
    sum += f;
    sum2 += f * f;
  }
  const double mean = sum / samples;
  return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples)};
}

TEST(LightSetTree, IrradianceFromManyLightsMatchesTheClosedForm) {
  const ManyLights m = manyLights(21);
  const MaterialTable materials(m.scene);
  const Environment black;
  const Bounds3f bounds{{-9, 0, -9}, {9, 5, 9}};
  const LightSet tree(materials, black, bounds, LightSampling::Tree);
  const LightSet power(materials, black, bounds, LightSampling::Power);
  // On the ground facing up, so that every light is above the horizon (the
  // closed form for a triangle holds there).
  const Vec3f points[] = {{0, 0, 0}, {5, 0, -6}, {-7, 0, 7}};
  const Vec3f n{0, 1, 0};
  for (int k = 0; k < 3; ++k) {
    const double exact = exactIrradiance(m, points[k], n);
    const Estimate t = estimateIrradiance(tree, points[k], n, 200000, 31 + k);
    const Estimate w = estimateIrradiance(power, points[k], n, 200000, 31 + k);
    std::printf("point %d: exact %.5f, tree %.5f (standard error %.5f), power %.5f (%.5f)\n", k, exact,
                t.mean, t.standardError, w.mean, w.standardError);
    EXPECT_LT(std::abs(t.mean - exact), 4 * t.standardError)
        << "tree, point " << k << ": " << t.mean << " for " << exact << ", standard error "
        << t.standardError;
    EXPECT_LT(std::abs(w.mean - exact), 4 * w.standardError)
        << "power, point " << k << ": " << w.mean << " for " << exact;
    // What the tree is for: less noise for the same samples (this scene
    // spreads its lights evenly, so the gain is modest: variance 0.42x at
    // the centre).
    EXPECT_LT(t.standardError, 0.8 * w.standardError) << "point " << k;
  }
  // Injected bugs (measured): the tree's pmf reported 10% high for picks
  // that take the root's second child: 1.7206 for 1.7525 at point 0 (6.3
  // standard errors), 1.3878 for 1.5224 at point 1 (32); spots bounded
  // without their spread (cos theta_e = 1): never picked, 0.933 for 1.522
  // at point 1 (280 standard errors).
}

// The light point of a sample, and which triangle of the mesh it lies on.
std::optional<unsigned> triangleUnder(const ManyLights& m, const Vec3f& q) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& v = m.triangles[t];
    const Vec3f e1 = v[1] - v[0], e2 = v[2] - v[0], normal = cross(e1, e2);
    const float area2 = length(normal);
    const Vec3f d = q - v[0];
    if (std::abs(dot(d, normal)) > 1e-4f * area2) continue;
    const float b1 = dot(cross(d, e2), normal) / (area2 * area2);
    const float b2 = dot(cross(e1, d), normal) / (area2 * area2);
    if (b1 >= -1e-4f && b2 >= -1e-4f && b1 + b2 <= 1 + 1e-4f) return unsigned(t);
  }
  return std::nullopt;
}

TEST(LightSetTree, PdfTriangleIsTheDensityOfTheSample) {
  const ManyLights m = manyLights(22);
  const MaterialTable materials(m.scene);
  const Environment sky = Environment::constant({0.2f, 0.2f, 0.2f});
  const Bounds3f bounds{{-9, 0, -9}, {9, 5, 9}};
  for (const LightSampling sampling : {LightSampling::Tree, LightSampling::Power}) {
    const LightSet lights(materials, sky, bounds, sampling);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    int triangles = 0, environment = 0;
    for (int k = 0; k < 10; ++k) {
      const Vec3f p{16 * u(rng) - 8, 0.5f * u(rng), 16 * u(rng) - 8};
      const Vec3f n = randomUnit(rng);
      double sum = 0;
      for (std::size_t i = 0; i < lights.lightCount(); ++i) sum += lights.pickProbability(i, p, n);
      // The tree may find no light (see above); power picks always find one.
      ASSERT_LE(sum, 1 + 1e-5);
      if (sampling == LightSampling::Power) {
        ASSERT_NEAR(sum, 1.0, 1e-5);
      }
      for (int s = 0; s < 2000; ++s) {
        const float uPick = u(rng), u1 = u(rng), u2 = u(rng);
        const std::optional<LightSample> ls = lights.sample(p, n, uPick, {u1, u2});
        if (!ls || ls->delta) continue;
        if (!std::isfinite(ls->distance)) {
          EXPECT_NEAR(lights.pdfEnvironment(ls->wi), ls->pdf, 1e-4 * ls->pdf);
          ++environment;
          continue;
        }
        const Vec3f q = p + ls->wi * ls->distance;
        const std::optional<unsigned> t = triangleUnder(m, q);
        ASSERT_TRUE(t);
        const auto& v = m.triangles[*t];
        const Vec3f normal = normalize(cross(v[1] - v[0], v[2] - v[0]));
        EXPECT_NEAR(lights.pdfTriangle(0, *t, p, n, q, normal), ls->pdf, 2e-3 * ls->pdf)
            << lightSamplingName(sampling);
        ++triangles;
      }
    }
    EXPECT_GT(triangles, 200);
    EXPECT_GT(environment, 10);
  }
}

// --- a furnace room of many emitters -----------------------------------------

// The inside of the cube [-1, 1]^3, each face cut into k x k squares (two
// triangles each) facing in.
Mesh roomOfTiles(int k) {
  Mesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f})
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const auto at = [&](float a, float b) {
            Vec3f v;
            v[axis] = side;
            v[(axis + 1) % 3] = -1 + 2 * a / float(k);
            v[(axis + 2) % 3] = -1 + 2 * b / float(k);
            return v;
          };
          const std::uint32_t base = std::uint32_t(m.positions.size());
          m.positions.insert(m.positions.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
          // Counter-clockwise seen from inside: the +side wall's front looks toward -axis.
          if (side > 0)
            m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
          else
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
  return m;
}

// Every wall emits Le = 1 and reflects albedo a = 0.5 (Lambertian): inside,
// the radiance is Le (1 + a + ... + a^D) for paths of D scattering events.
TEST(LightSetTree, FurnaceRoomOfManyEmittersRendersItsClosedForm) {
  SceneDesc scene;
  scene.sourceFile = "room of tiles (in code)";
  Mesh room = roomOfTiles(8);  // 768 emissive triangles
  room.material = 0;
  scene.meshes.push_back(room);
  Material wall = test::whiteMatte();
  wall.baseColor = {0.5f, 0.5f, 0.5f, 1};
  wall.emissive = {1, 1, 1};
  scene.materials.push_back(wall);
  scene.instances.push_back({0, Transform()});
  const PinholeCamera camera(Transform::lookAt({0.2f, -0.3f, 0.4f}, {-1, 0.2f, -1}, {0, 1, 0}),
                             {24, 24, 36, 24}, 70 * kPi / 180);
  constexpr int kDepth = 3;
  const double expected = 1 + 0.5 + 0.25 + 0.125;
  Estimate estimates[2];
  for (const LightSampling sampling : {LightSampling::Tree, LightSampling::Power}) {
    test::TestRenderSetup setup;
    setup.integrator.maxDepth = kDepth;
    setup.integrator.rouletteDepth = 100;
    setup.render.samplesPerPixel = 64;
    setup.render.aovs.variance = true;
    setup.lightSampling = sampling;
    const Image img = test::renderTestScene(scene, camera, setup);
    const int r = img.channelIndex("R"), v = img.channelIndex("variance.R");
    double sum = 0, variance = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        sum += img.at(x, y, r);
        variance += img.at(x, y, v);
      }
    const double pixels = double(img.width) * img.height;
    Estimate& e = estimates[sampling == LightSampling::Tree ? 0 : 1];
    e = {sum / pixels, std::sqrt(variance) / pixels};
    EXPECT_LT(std::abs(e.mean - expected), 4 * e.standardError)
        << lightSamplingName(sampling) << ": " << e.mean << " for " << expected << ", standard error "
        << e.standardError;
    std::printf("%s: mean %.5f for %.5f, standard error %.5f\n", lightSamplingName(sampling), e.mean,
                expected, e.standardError);
  }
  const double se = std::hypot(estimates[0].standardError, estimates[1].standardError);
  EXPECT_LT(std::abs(estimates[0].mean - estimates[1].mean), 4 * se)
      << "tree " << estimates[0].mean << ", power " << estimates[1].mean;
  // Injected bug (measured): pdfTriangle taking the tree's pmf without the
  // normal (n = 0) while sample() uses it, so that the MIS weights no longer
  // add up to 1: the tree's mean 1.8802 for 1.875, 5.7 standard errors off
  // (0.00091), and 3.4 from power's 1.8757 (the right tree gives 1.8749).
}

}  // namespace
}  // namespace lensrt
