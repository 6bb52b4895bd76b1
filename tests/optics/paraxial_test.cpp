// First-order optics against closed-form results.
#include "optics/paraxial.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics_test_util.h"

namespace lensrt {
namespace {

TEST(Paraxial, SeedDoubleGaussMatchesTheLecture) {
  const ParaxialData p = computeParaxial(test::libraryLens("dgauss-100mm"));
  EXPECT_NEAR(p.efl, 100.7, 0.1);
  EXPECT_NEAR(p.bfl, 72.2, 0.1);
  // Scaled by 0.5 (pbrt's dgauss.50mm.dat): EFL about 50.4 mm.
  EXPECT_NEAR(computeParaxial(test::libraryLens("dgauss-50mm")).efl, 50.4, 0.1);
  EXPECT_NEAR(computeParaxial(test::libraryLens("dgauss-100mm").scaled(0.5)).efl, 50.4, 0.1);
}

// Lensmaker's equation for a thick lens in air:
// 1/f = (n-1) [1/R1 - 1/R2 + (n-1) t / (n R1 R2)], BFL = f (1 - (n-1) t / (n R1)).
TEST(Paraxial, SingletMatchesLensmakersFormula) {
  for (const auto& [r1, r2, t, n] :
       {std::tuple{100.0, -100.0, 0.001, 1.5}, std::tuple{60.0, -200.0, 8.0, 1.7},
        std::tuple{50.0, 150.0, 5.0, 1.6}, std::tuple{-80.0, -40.0, 6.0, 1.5}}) {
    const ParaxialData p = computeParaxial(test::singlet(r1, r2, t, n));
    const double f = 1.0 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    EXPECT_NEAR(p.efl, f, 1e-9 * std::abs(f));
    EXPECT_NEAR(p.bfl, f * (1 - (n - 1) * t / (n * r1)), 1e-9 * std::abs(f));
    EXPECT_NEAR(p.ffl, f * (1 + (n - 1) * t / (n * r2)), 1e-9 * std::abs(f));
  }
}

TEST(Paraxial, SymmetricLensHasSymmetricPrincipalPlanes) {
  // Biconvex, and a symmetric doublet with the stop in the middle.
  LensPrescription lens = test::singlet(80.0, -80.0, 10.0, 1.6);
  ParaxialData p = computeParaxial(lens);
  EXPECT_NEAR(p.frontPrincipalZ + p.rearPrincipalZ, p.lastVertexZ, 1e-9);
  EXPECT_NEAR(p.bfl, p.ffl, 1e-9);
  EXPECT_GT(p.rearPrincipalZ, p.frontPrincipalZ);  // biconvex: H in front of H'
  LensPrescription sym;
  sym.name = "symmetric";
  auto add = [&](double r, double t, double n, bool stop = false) {
    Surface s;
    s.radius = r;
    s.thickness = t;
    s.apertureDiameter = 20;
    s.medium.nd = n;
    s.isStop = stop;
    sym.surfaces.push_back(s);
  };
  add(40, 5, 1.7);
  add(120, 4, 1.0);
  add(0, 4, 1.0, true);
  add(-120, 5, 1.7);
  add(-40, 0, 1.0);
  p = computeParaxial(sym);
  EXPECT_NEAR(p.frontPrincipalZ + p.rearPrincipalZ, p.lastVertexZ, 1e-9);
  EXPECT_NEAR(p.bfl, p.ffl, 1e-9);
  // Pupils mirror each other about the stop too.
  EXPECT_NEAR(p.entrancePupilZ + p.exitPupilZ, p.lastVertexZ, 1e-9);
  EXPECT_NEAR(p.entrancePupilDiameter, p.exitPupilDiameter, 1e-9);
}

TEST(Paraxial, StopInFrontIsItsOwnEntrancePupil) {
  const ParaxialData p = computeParaxial(test::singlet(100.0, -100.0, 5.0, 1.5, 12.5));
  EXPECT_NEAR(p.entrancePupilZ, 0.0, 1e-12);
  EXPECT_NEAR(p.entrancePupilDiameter, 12.5, 1e-12);
  EXPECT_NEAR(p.fNumber, p.efl / 12.5, 1e-9);
  // The exit pupil is the virtual image of the stop through the lens: for a
  // thin lens, 1/v - 1/u = 1/f with u = -(distance to H).
  const double u = -(p.frontPrincipalZ - p.stopZ);
  const double v = 1.0 / (1.0 / p.efl + 1.0 / u);
  EXPECT_NEAR(p.exitPupilZ, p.rearPrincipalZ + v, 1e-9);
  EXPECT_NEAR(p.exitPupilDiameter, 12.5 * v / u, 1e-9);
}

TEST(Paraxial, ConjugatesObeyTheLensEquation) {
  const ParaxialData p = computeParaxial(test::libraryLens("dgauss-50mm"));
  for (const double s : {200.0, 1000.0, 5000.0}) {
    const Conjugate c = paraxialConjugate(p, s);
    // Newton's form: x x' = -f^2 with x, x' from the focal points.
    const double x = (p.entrancePupilZ - s) - p.frontFocalZ;
    const double xPrime = c.imageZ - p.rearFocalZ;
    EXPECT_NEAR(x * xPrime, -p.efl * p.efl, 1e-9 * p.efl * p.efl);
    EXPECT_NEAR(c.magnification, -p.efl / (-x), 1e-12);
  }
  const Conjugate inf = paraxialConjugate(p, std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(inf.filmDistance, p.bfl);
  EXPECT_THROW(paraxialConjugate(p, 10.0), std::domain_error);
}

TEST(Paraxial, FieldOfViewOfAFullFrameNormalLens) {
  // 50 mm on 36x24: 46.8 deg diagonal, 39.6 horizontal, 27.0 vertical.
  const FieldOfView fov = fieldOfView(50.0, 36.0, 24.0);
  EXPECT_NEAR(fov.diagonalDeg, 46.79, 0.01);
  EXPECT_NEAR(fov.horizontalDeg, 39.60, 0.01);
  EXPECT_NEAR(fov.verticalDeg, 26.99, 0.01);
}

// The seed's D_N and D_F, checked against the geometry they come from: at
// each limit, a thin lens of aperture f/N images the object to a blur circle
// of exactly c on the film placed for the focus distance.
TEST(Paraxial, DepthOfFieldLimitsGiveBlurEqualToCircleOfConfusion) {
  const double f = 50.0, N = 2.8, c = 0.03;
  const auto imageOf = [&](double d) { return f * d / (d - f); };
  for (const double s : {500.0, 2000.0, 8000.0}) {
    const DepthOfField dof = depthOfField(f, N, c, s);
    EXPECT_NEAR(dof.nearLimit, s * f * f / (f * f + N * c * (s - f)), 1e-9 * s);
    const double vs = imageOf(s);
    const double blurNear = (f / N) * (imageOf(dof.nearLimit) - vs) / imageOf(dof.nearLimit);
    EXPECT_NEAR(blurNear, c, 1e-9);
    ASSERT_TRUE(std::isfinite(dof.farLimit));
    const double blurFar = (f / N) * (vs - imageOf(dof.farLimit)) / imageOf(dof.farLimit);
    EXPECT_NEAR(blurFar, c, 1e-9);
  }
  // At the hyperfocal distance the far limit reaches infinity and the near
  // limit is half of it (to first order in f/H).
  const double h = hyperfocalDistance(f, N, c);
  EXPECT_TRUE(std::isinf(depthOfField(f, N, c, h).farLimit));
  EXPECT_TRUE(std::isfinite(depthOfField(f, N, c, h * 0.99).farLimit));
  EXPECT_NEAR(depthOfField(f, N, c, h).nearLimit, h / 2, 0.5 * f);
}

}  // namespace
}  // namespace lensrt
