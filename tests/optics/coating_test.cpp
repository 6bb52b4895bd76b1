// Fresnel losses and coatings against the closed forms of thin-film optics.
#include "optics/coating.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include "core/warnings.h"
#include "optics/axial_transmittance.h"
#include "optics/focus.h"
#include "optics/lens_system.h"
#include "optics/sample_sequence.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

double square(double x) {
  return x * x;
}

TEST(Coating, NormalIncidenceMatchesTheClosedForms) {
  for (const double ns : {1.5, 1.52, 1.7, 1.9}) {
    // Bare glass: R = ((n1 - n2) / (n1 + n2))^2, either way through.
    const double bare = 1.0 - square((1.0 - ns) / (1.0 + ns));
    EXPECT_NEAR(surfaceTransmittance(Coating::None, 1.0, ns, 1.0, 1.0, 550.0), bare, 1e-14);
    EXPECT_NEAR(surfaceTransmittance(Coating::None, ns, 1.0, 1.0, 1.0, 550.0), bare, 1e-14);
    // A quarter-wave layer of index n1 at its design wavelength:
    // R = ((n0 ns - n1^2) / (n0 ns + n1^2))^2.
    const double n1 = 1.38;
    const double single = 1.0 - square((1.0 * ns - n1 * n1) / (1.0 * ns + n1 * n1));
    EXPECT_NEAR(surfaceTransmittance(Coating::Single, 1.0, ns, 1.0, 1.0, 550.0), single, 1e-14);
    EXPECT_NEAR(surfaceTransmittance(Coating::Single, ns, 1.0, 1.0, 1.0, 550.0), single, 1e-14);
    EXPECT_GT(single, bare);
    EXPECT_DOUBLE_EQ(surfaceTransmittance(Coating::Multi, 1.0, ns, 0.7, 0.9, 450.0), 0.995);
  }
  // A cemented interface is never coated: bare Fresnel between the glasses.
  EXPECT_NEAR(surfaceTransmittance(Coating::Multi, 1.5, 1.7, 1.0, 1.0, 550.0), 1.0 - square(0.2 / 3.2),
              1e-14);
  // Away from its design wavelength the layer is no longer a quarter wave:
  // it reflects more (its minimum is at 550 nm).
  EXPECT_LT(surfaceTransmittance(Coating::Single, 1.0, 1.7, 1.0, 1.0, 450.0),
            surfaceTransmittance(Coating::Single, 1.0, 1.7, 1.0, 1.0, 550.0));
}

// Oblique incidence on bare glass: the textbook forms in the angles,
// R_s = sin^2(i - t) / sin^2(i + t), R_p = tan^2(i - t) / tan^2(i + t).
TEST(Coating, ObliqueBareGlassMatchesFresnelsSineAndTangentLaws) {
  const double n = 1.6;
  for (const double deg : {5.0, 20.0, 45.0, 70.0, 85.0}) {
    const double i = deg * M_PI / 180.0, t = std::asin(std::sin(i) / n);
    const double rs = square(std::sin(i - t) / std::sin(i + t)),
                 rp = square(std::tan(i - t) / std::tan(i + t));
    const double expected = 1.0 - 0.5 * (rs + rp);
    EXPECT_NEAR(surfaceTransmittance(Coating::None, 1.0, n, std::cos(i), std::cos(t), 587.6), expected, 1e-12)
        << deg;
    // The same from inside the glass (reciprocity).
    EXPECT_NEAR(surfaceTransmittance(Coating::None, n, 1.0, std::cos(t), std::cos(i), 587.6), expected, 1e-12)
        << deg;
    // A single layer helps at any angle up to far off normal.
    if (deg < 60.0) {
      EXPECT_GT(surfaceTransmittance(Coating::Single, 1.0, n, std::cos(i), std::cos(t), 550.0), expected)
          << deg;
    }
  }
}

TEST(Coating, Names) {
  EXPECT_EQ(parseCoating("single"), Coating::Single);
  EXPECT_EQ(parseCoating("multi"), Coating::Multi);
  EXPECT_EQ(parseCoating("none"), Coating::None);
  EXPECT_FALSE(parseCoating("MgF2"));
  EXPECT_EQ(coatingName(Coating::Single), "single");
}

// The seed's double Gauss, uncoated: the axial bundle's transmittance is the
// product over its refracting surfaces of the normal-incidence terms
// 1 - ((n1 - n2) / (n1 + n2))^2. Unpolarised Fresnel reflectance is flat to
// second order in the angle, so a thin pencil (f/64) matches to 1e-4 and the
// f/4 bundle within 0.5%; wide open (f/2) its marginal rays meet the strong
// inner surfaces at up to ~30 degrees and the bundle loses a little more.
TEST(Coating, UncoatedDoubleGaussTransmitsTheProductOfTheFresnelTerms) {
  const LensPrescription rx = test::libraryLens("dgauss-100mm");
  double expected = 1.0, nBefore = 1.0;
  int refracting = 0;
  for (const Surface& s : rx.surfaces) {
    const double n1 = nBefore, n2 = s.medium.nd;
    if (!s.isStop && n1 != n2) {
      expected *= 1.0 - square((n1 - n2) / (n1 + n2));
      ++refracting;
    }
    nBefore = n2;
  }
  EXPECT_EQ(refracting, 10);  // six elements, two cemented pairs: 10 refracting surfaces
  Warnings warnings;
  const auto at = [&](double fNumber, Coating coating) {
    return axialTransmittance(LensSystem(stopDown(rx, fNumber, warnings), coating));
  };
  const double pencil = at(64.0, Coating::None), f4 = at(4.0, Coating::None);
  const double wideOpen = axialTransmittance(LensSystem(rx, Coating::None));
  EXPECT_NEAR(pencil / expected, 1.0, 1e-4) << pencil << " vs " << expected;
  EXPECT_NEAR(f4 / expected, 1.0, 0.005) << f4 << " vs " << expected;
  EXPECT_LT(wideOpen, f4);
  EXPECT_NEAR(wideOpen / expected, 1.0, 0.01) << wideOpen << " vs " << expected;

  // Single layer: every glass-air surface gets the quarter-wave reflectance
  // at 550 nm, ((ns - n1^2) / (ns + n1^2))^2 from air; the pencil is traced
  // at the d line (587.6 nm), where the layer is 550/587.6 of a quarter
  // wave, so the expectation uses the general single-layer form
  // R = (r01^2 + r12^2 + 2 r01 r12 cos 2b) / (1 + r01^2 r12^2 + 2 r01 r12 cos 2b)
  // with b = (pi / 2) 550 / 587.6. Cemented surfaces stay bare.
  const double nl = 1.38, beta = 0.5 * M_PI * 550.0 / 587.6;
  double single = 1.0, quarter = 1.0, multi = 1.0;
  nBefore = 1.0;
  for (const Surface& s : rx.surfaces) {
    const double n1 = nBefore, n2 = s.medium.nd;
    nBefore = n2;
    if (s.isStop || n1 == n2) continue;
    if (n1 != 1.0 && n2 != 1.0) {
      single *= 1.0 - square((n1 - n2) / (n1 + n2));
      quarter *= 1.0 - square((n1 - n2) / (n1 + n2));
      multi *= 1.0 - square((n1 - n2) / (n1 + n2));
      continue;
    }
    const double ns = std::max(n1, n2);
    const double r01 = (1.0 - nl) / (1.0 + nl), r12 = (nl - ns) / (nl + ns);
    const double c = 2.0 * r01 * r12 * std::cos(2.0 * beta);
    single *= 1.0 - (r01 * r01 + r12 * r12 + c) / (1.0 + r01 * r01 * r12 * r12 + c);
    quarter *= 1.0 - square((ns - nl * nl) / (ns + nl * nl));
    multi *= 1.0 - 0.005;
  }
  const double singlePencil = at(64.0, Coating::Single);
  EXPECT_NEAR(singlePencil / single, 1.0, 1e-4) << singlePencil << " vs " << single;
  // Slightly off its design wavelength the layer does nearly as well as a
  // true quarter wave (0.5% less over the lens's eight coated surfaces).
  EXPECT_LT(singlePencil, quarter);
  EXPECT_NEAR(singlePencil / quarter, 1.0, 0.01) << singlePencil << " vs " << quarter;
  EXPECT_GT(singlePencil, pencil);
  // Ideal multilayer: 0.995 per glass-air surface, cemented bare.
  const double multiPencil = at(64.0, Coating::Multi);
  EXPECT_NEAR(multiPencil / multi, 1.0, 1e-4) << multiPencil << " vs " << multi;
  // Lossless: everything.
  EXPECT_EQ(axialTransmittance(LensSystem(rx)), 1.0);
}

// Without a coating model the trace leaves the transmittance alone; with one,
// the batched film trace still equals the one-ray trace, transmittance too.
TEST(Coating, BatchedTraceCarriesTheSameTransmittance) {
  const LensPrescription rx = test::libraryLens("dgauss-50mm");
  const LensSystem plain(rx), coated(rx, Coating::Single);
  SplitMix64 rng(4);
  std::vector<LensRay> rays;
  const double rear = plain.rearApertureRadius();
  for (int i = 0; i < 203; ++i) {
    const Vec3d film{(2 * rng.uniform() - 1) * rear, (2 * rng.uniform() - 1) * rear, plain.rearZ() + 40};
    const Vec3d aim{(2 * rng.uniform() - 1) * rear, (2 * rng.uniform() - 1) * rear, plain.rearZ()};
    rays.push_back({film, aim - film});
  }
  std::vector<std::optional<LensRay>> batched(rays.size());
  coated.traceFromFilm(rays, batched);
  int passed = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto one = coated.traceFromFilm(rays[i]);
    const auto lossless = plain.traceFromFilm(rays[i]);
    ASSERT_EQ(one.has_value(), batched[i].has_value());
    ASSERT_EQ(one.has_value(), lossless.has_value());
    if (!one) continue;
    ++passed;
    EXPECT_EQ(std::memcmp(&one->direction, &batched[i]->direction, sizeof(Vec3d)), 0);
    EXPECT_EQ(one->transmittance, batched[i]->transmittance);
    // The coating changes the weight, never the geometry.
    EXPECT_EQ(std::memcmp(&one->direction, &lossless->direction, sizeof(Vec3d)), 0);
    EXPECT_EQ(lossless->transmittance, 1.0);
    EXPECT_GT(one->transmittance, 0.8);
    EXPECT_LT(one->transmittance, 1.0);
  }
  EXPECT_GT(passed, 20);
}

}  // namespace
}  // namespace lensrt
