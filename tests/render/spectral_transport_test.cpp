// Spectral transport against closed forms: under the CIE 1931 observer and
// sRGB output a glTF colour renders back as itself (Jakob-Hanika upsampling
// integrates to the colour under D65), the white furnace renders 1, and a
// dispersive glass slab (KHR_materials_dispersion), which dispersion leaves
// radiometrically unchanged, transmits what the same glass without dispersion
// does: the hero wavelength's weight after the others are dropped is right.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/film_response.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/test_scene_util.h"
#include "render/wavelengths.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

const FilmResponse& cie() {
  return FilmResponse::cie1931Srgb();
}

// The colours of the round-trip table: a 5^3 grid and the sRGB primaries and
// secondaries at full and half strength.
std::vector<Rgb> colourGrid() {
  std::vector<Rgb> colours;
  for (int r = 0; r <= 4; ++r)
    for (int g = 0; g <= 4; ++g)
      for (int b = 0; b <= 4; ++b) colours.push_back(Rgb{float(r), float(g), float(b)} * 0.25f);
  for (const float s : {1.0f, 0.5f})
    for (const Rgb c : {Rgb{1, 0, 0}, Rgb{0, 1, 0}, Rgb{0, 0, 1}, Rgb{1, 1, 0}, Rgb{0, 1, 1}, Rgb{1, 0, 1}})
      colours.push_back(c * s);
  return colours;
}

// Within 1% of the channel, or `floor` absolute for a channel near 0.
void expectColour(const Rgb& got, const Rgb& want, const std::string& what, float floor = 0.002f) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], std::max(0.01f * want[c], floor)) << what << " channel " << c;
}

std::string text(const Rgb& c) {
  return "rgb (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ")";
}

// The expected film value of a reflectance lit by RGB (1, 1, 1) light, over
// stratified wavelength samples (the renderer's 1D stream is stratified too).
TEST(SpectralTransport, ReflectanceUnderWhiteLightIsItsOwnColour) {
  constexpr int kN = 4096;
  for (const Rgb& colour : colourGrid()) {
    Rgb sum{0, 0, 0};
    for (int i = 0; i < kN; ++i) {
      const SampledWavelengths lambda = SampledWavelengths::sample((float(i) + 0.5f) / kN, cie());
      sum += lambda.toFilm(lambda.reflectance(colour) * lambda.illuminant(Rgb{1, 1, 1}));
    }
    expectColour(sum / float(kN), colour, text(colour));
  }
}

// Light of any colour, and above 1, on a white reflector records as itself:
// scaled into the table by 1 / (2 max), a channel far below the largest
// keeps the table's absolute error (about 3e-4 of the scale), so the floor
// is 0.1% of the largest channel.
TEST(SpectralTransport, LightColoursAndUnboundedValuesRoundTrip) {
  constexpr int kN = 4096;
  for (const Rgb& colour :
       {Rgb{1, 1, 1}, Rgb{20, 20, 20}, Rgb{50, 10, 2}, Rgb{0.3f, 4, 0.1f}, Rgb{0, 0, 7}}) {
    Rgb light{0, 0, 0}, factor{0, 0, 0};
    for (int i = 0; i < kN; ++i) {
      const SampledWavelengths lambda = SampledWavelengths::sample((float(i) + 0.5f) / kN, cie());
      light += lambda.toFilm(lambda.illuminant(colour));
      factor += lambda.toFilm(lambda.unbounded(colour) * lambda.illuminant(Rgb{1, 1, 1}));
    }
    const float floor = 0.001f * maxComponent(colour);
    expectColour(light / float(kN), colour, "light " + text(colour), floor);
    expectColour(factor / float(kN), colour, "unbounded factor " + text(colour), floor);
  }
}

TEST(SpectralTransport, WavelengthDensityIsNormalisedAndSampledByItsInverse) {
  // The density integrates to 1 over 360-830 nm (the midpoint rule at 0.1 nm).
  double integral = 0;
  for (double nm = 360.05; nm < 830; nm += 0.1) integral += cie().wavelengthPdf(float(nm)) * 0.1;
  EXPECT_NEAR(integral, 1.0, 2e-3);
  // The sampler's CDF: a quarter of the samples below the first quartile.
  for (const float u : {0.1f, 0.25f, 0.5f, 0.9f}) {
    const FilmResponse::WavelengthDraw draw = cie().sampleWavelength(u);
    EXPECT_FLOAT_EQ(draw.pdf, cie().wavelengthPdf(draw.nm));
    const float q = draw.nm;
    double below = 0;
    for (double nm = 360.005; nm < q; nm += 0.01) below += cie().wavelengthPdf(float(nm)) * 0.01;
    EXPECT_NEAR(below, u, 2e-3) << u;
  }
}

TEST(SpectralTransport, DroppingTheSecondaryWavelengthsKeepsTheExpectation) {
  constexpr int kN = 8192;
  const Rgb colour{0.8f, 0.3f, 0.1f};
  Rgb sum{0, 0, 0};
  for (int i = 0; i < kN; ++i) {
    SampledWavelengths lambda = SampledWavelengths::sample((float(i) + 0.5f) / kN, cie());
    lambda.terminateSecondary();
    EXPECT_EQ(lambda.liveLanes(), Spectrum(1, 0, 0, 0));
    sum += lambda.toFilm(lambda.reflectance(colour) * lambda.illuminant(Rgb{1, 1, 1}));
  }
  expectColour(sum / float(kN), colour, "hero only");
}

// A Lambertian card under a uniform white sky, traced by the integrator:
// radiance = albedo.
struct SkyTracer {
  static MaterialTable lambert(const SceneDesc& desc) {
    MaterialTable m(desc);
    for (std::size_t i = 0; i < desc.materials.size(); ++i) m.extra(int(i)).specularWeight = 0;
    return m;
  }
  static IntegratorSettings depth(int maxDepth) {
    IntegratorSettings s;
    s.maxDepth = maxDepth;
    return s;
  }
  SkyTracer(SceneDesc desc, int maxDepth, Rgb sky)
      : scene(std::move(desc)),
        materials(lambert(scene.desc())),
        environment(Environment::constant(sky)),
        lights(materials, environment, scene.bounds()),
        integrator(scene, materials, lights, environment, depth(maxDepth)) {}
  Rgb mean(const Ray& ray, int n, bool spectral) const {
    Rgb sum{0, 0, 0};
    for (int i = 0; i < n; ++i) {
      const SampledWavelengths lambda = spectral
                                            ? SampledWavelengths::sample((float(i) + 0.5f) / float(n), cie())
                                            : SampledWavelengths::rgb();
      sum += integrator.trace(ray, Sampler(3, 0, std::uint32_t(i)), lambda).radiance;
    }
    return sum / float(n);
  }
  RenderScene scene;
  MaterialTable materials;
  Environment environment;
  LightSet lights;
  Integrator integrator;
};

SceneDesc card(const Rgb& colour) {
  SceneDesc s;
  s.sourceFile = "card (in code)";
  s.meshes.push_back(test::makeQuadY(0, 1000));
  s.meshes[0].material = 0;
  s.instances.push_back({0, Transform()});
  s.materials = {test::whiteMatte()};
  s.materials[0].baseColor = {colour.x, colour.y, colour.z, 1};
  return s;
}

TEST(SpectralTransport, DiffuseCardUnderWhiteSkyRendersItsColour) {
  const Ray ray{{0, 1, 0}, normalize(Vec3f{0.2f, -1, 0.1f}), 0, kInfinityF};
  for (const Rgb& colour : {Rgb{0.75f, 0.25f, 0.5f}, Rgb{0.1f, 0.9f, 0.3f}, Rgb{1, 1, 0},
                            Rgb{0.2f, 0.2f, 0.9f}, Rgb{0.5f, 0.5f, 0.5f}}) {
    const SkyTracer tracer(card(colour), 1, {1, 1, 1});
    expectColour(tracer.mean(ray, 16384, true), colour, "card " + text(colour));
  }
}

// A white Lambertian sphere in the white furnace vanishes: 1 in every channel.
TEST(SpectralTransport, WhiteFurnaceRendersOne) {
  SceneDesc s;
  s.sourceFile = "furnace (in code)";
  s.meshes.push_back(test::makeSphere({0, 0, 0}, 1, 24, 48));
  s.meshes[0].material = 0;
  s.instances.push_back({0, Transform()});
  s.materials = {test::whiteMatte()};
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {32, 32, 36, 24},
                             35 * kPi / 180);
  test::TestRenderSetup setup;
  setup.environment = Environment::constant({1, 1, 1});
  setup.integrator.maxDepth = 8;
  setup.render.samplesPerPixel = 16;
  setup.render.seed = 1;
  setup.render.filmResponse = std::shared_ptr<const FilmResponse>(std::shared_ptr<const void>(), &cie());
  const Image img = test::renderTestScene(std::move(s), camera, setup);
  for (const char* c : {"R", "G", "B"}) EXPECT_NEAR(test::channelMean(img, c), 1.0, 0.002) << c;
}

// Dispersion through a parallel slab only shifts rays sideways: in front of
// a uniform emitter the slab transmits the same light, dispersive or not,
// and white stays white. Only the hero wavelength crosses the dispersive
// glass, so this checks its weight (x4) and that the others were dropped.
TEST(SpectralTransport, DispersiveSlabTransmitsWhatPlainGlassDoes) {
  const auto slab = [](float dispersion) {
    SceneDesc s;
    s.sourceFile = "slab (in code)";
    s.meshes.push_back(test::makeBox({-50, -1, -50}, {50, 0, 50}));
    s.meshes[0].material = 0;
    s.instances.push_back({0, Transform()});
    Material glass;
    glass.baseColor = {1, 1, 1, 1};
    glass.metallic = 0;
    glass.roughness = 0;
    glass.transmission = 1;
    glass.ior = 1.5f;
    glass.thickness = 1;
    glass.dispersion = dispersion;
    s.materials = {glass};
    return s;
  };
  // Looking down through the slab at a white sky below it (the sky is uniform).
  const Ray ray{{0, 1, 0}, normalize(Vec3f{0.3f, -1, 0.2f}), 0, kInfinityF};
  constexpr int kN = 16384;
  const SkyTracer plain(slab(0), 16, {1, 1, 1});
  const SkyTracer dispersive(slab(20.0f / 20.0f), 16, {1, 1, 1});  // Abbe number 20: strong flint
  const Rgb a = plain.mean(ray, kN, true), b = dispersive.mean(ray, kN, true);
  // Every path ends in the sky: the furnace again, through glass.
  expectColour(a, {1, 1, 1}, "plain glass");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], a[c], 0.02) << "channel " << c;
}

TEST(SpectralTransport, DispersionFollowsTheAbbeNumber) {
  Material m;
  m.ior = 1.7f;
  m.dispersion = 20.0f / 25.0f;  // V = 25
  // n_F - n_C = (n_d - 1) / V, n(d line) = n_d (the extension's definition).
  EXPECT_NEAR(m.iorAt(486.13f) - m.iorAt(656.27f), 0.7 / 25, 2e-4);
  EXPECT_NEAR(m.iorAt(587.56f), 1.7, 2e-4);
  m.dispersion = 0;
  EXPECT_EQ(m.iorAt(400), 1.7f);
}

}  // namespace
}  // namespace lensrt
