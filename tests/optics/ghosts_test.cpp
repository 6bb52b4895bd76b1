// optics/ghosts: the paraxial ghosts of a lens against closed forms. A
// singlet's one ghost (reflected at its rear surface, then at its front) is
// followed here by Gaussian imaging, surface by surface (the refraction
// equation n'/s' - n/s = (n' - n)/R, and a mirror as n' = -n), with its
// heights by similar triangles: a different route from the code's ray
// slopes. Strengths are the Fresnel and single-layer formulas at normal
// incidence.
#include "optics/ghosts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/lens_system.h"
#include "optics/paraxial.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

struct ExpectedGhost {
  double focusZ = 0.0;  // from the first lens vertex
  double sizeOnFilm = 0.0;
  double passing = 0.0;
};

// The singlet's ghost for light from infinity entering at height h (the stop's
// radius, at the front vertex), with lens apertures of radius `lensRadius`.
ExpectedGhost singletGhost(double r1, double r2, double t, double n, double stopRadius, double lensRadius) {
  // Refraction into the glass at the front vertex (z = 0).
  const double s1 = n * r1 / (n - 1);
  // The rear surface as a mirror in glass: 1/s' + 1/s = 2/R, s from its vertex.
  const double s2 = 1.0 / (2.0 / r2 - 1.0 / (s1 - t));
  // Back at the front surface, a mirror again (in glass), s from the front vertex.
  const double s3 = 1.0 / (2.0 / r1 - 1.0 / (t + s2));
  // Out through the rear surface: 1/s' - n/s = (1 - n)/R2.
  const double s4 = 1.0 / ((1 - n) / r2 + n / (s3 - t));
  // Heights per unit entrance height: each segment aims at the next image.
  const double y2 = 1 - t / s1;          // at the rear vertex, heading for z = s1
  const double y3 = y2 * (t + s2) / s2;  // back at the front vertex, heading for z = t + s2
  const double y4 = y3 * (s3 - t) / s3;  // at the rear vertex again, heading for z = s3
  const double f = 1.0 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
  const double filmZ = t + f * (1 - (n - 1) * t / (n * r1));  // rear focal point
  const double yFilm = y4 * (t + s4 - filmZ) / s4;
  const double h = std::min({stopRadius, lensRadius / std::abs(y2), lensRadius / std::abs(y3),
                             lensRadius / std::abs(y4), lensRadius});
  return {t + s4, 2 * h * std::abs(yFilm), h * h / (stopRadius * stopRadius)};
}

TEST(Ghosts, ASingletsGhostFocusesWhereGaussianImagingPutsIt) {
  struct Case {
    double r1, r2, t, n, lensRadius;
  };
  for (const Case c : {Case{80, -80, 10, 1.6, 30}, Case{50, 120, 6, 1.7, 30}, Case{100, -300, 8, 1.5, 30},
                       Case{60, -60, 12, 1.8, 6}}) {
    SCOPED_TRACE(testing::Message() << "R1 " << c.r1 << " R2 " << c.r2 << " t " << c.t << " n " << c.n);
    LensPrescription lens = test::singlet(c.r1, c.r2, c.t, c.n, 10.0);
    lens.surfaces[1].apertureDiameter = lens.surfaces[2].apertureDiameter = 2 * c.lensRadius;
    const std::vector<GhostPath> ghosts = ghostPaths(lens, Coating::None);
    ASSERT_EQ(ghosts.size(), 1u);  // the stop reflects nothing
    const GhostPath& g = ghosts[0];
    EXPECT_EQ(g.first, 2);
    EXPECT_EQ(g.second, 1);
    const ExpectedGhost want = singletGhost(c.r1, c.r2, c.t, c.n, 5.0, c.lensRadius);
    const ParaxialData p = computeParaxial(lens);
    ASSERT_TRUE(g.focusFromFilmMm);
    EXPECT_NEAR(*g.focusFromFilmMm, want.focusZ - p.rearFocalZ, 1e-9 * std::abs(want.focusZ) + 1e-9);
    EXPECT_NEAR(g.sizeOnFilmMm, want.sizeOnFilm, 1e-9 * want.sizeOnFilm + 1e-12);
    EXPECT_NEAR(g.passing, want.passing, 1e-12);
    // Uncoated glass: the Fresnel reflectance ((n - 1) / (n + 1))^2 at each surface.
    const double r = std::pow((c.n - 1) / (c.n + 1), 2);
    EXPECT_NEAR(g.strength, r * r, 1e-12);
  }
}

TEST(Ghosts, CoatingsSetTheStrength) {
  const double n = 1.6;
  const LensPrescription lens = test::singlet(80, -80, 10, n, 10.0);
  // A quarter-wave of MgF2 at its design wavelength: ((n0 ns - n1^2) / (n0 ns + n1^2))^2.
  const double single = std::pow((n - 1.38 * 1.38) / (n + 1.38 * 1.38), 2);
  EXPECT_NEAR(ghostPaths(lens, Coating::Single)[0].strength, single * single, 1e-9);
  EXPECT_NEAR(ghostPaths(lens, Coating::Multi)[0].strength, 0.005 * 0.005, 1e-12);
}

// A library lens: every pair of its surfaces where the index changes (the
// stop is not one), strongest first; a ghost that leaves parallel has no focus.
TEST(Ghosts, EveryPairOfReflectingSurfacesStrongestFirst) {
  const LensPrescription lens = test::libraryLens("dgauss-50mm");
  int reflecting = 0;
  for (std::size_t k = 0; k < lens.surfaces.size(); ++k)
    reflecting += (k > 0 ? lens.surfaces[k - 1].medium.nd : 1.0) != lens.surfaces[k].medium.nd;
  const std::vector<GhostPath> ghosts = strongestGhosts(lens, Coating::None);
  EXPECT_EQ(int(ghosts.size()), reflecting * (reflecting - 1) / 2);
  for (std::size_t i = 0; i < ghosts.size(); ++i) {
    EXPECT_GT(ghosts[i].first, ghosts[i].second);
    EXPECT_FALSE(lens.surfaces[std::size_t(ghosts[i].first)].isStop);
    EXPECT_GT(ghosts[i].passing, 0.0);
    if (i > 0) {
      EXPECT_LE(ghosts[i].strength, ghosts[i - 1].strength);
    }
  }
}

// The exact trace of a ghost (LensSystem::traceGhostFromScene) near the axis
// is the paraxial ghost: an axial ray at a small height crosses the axis at
// the paraxial focus, and carries R_i R_j (bare glass at normal incidence).
TEST(Ghosts, TheExactTraceNearTheAxisMeetsTheParaxialGhost) {
  for (const char* name : {"dgauss-50mm", "tessar-100mm"}) {
    SCOPED_TRACE(name);
    const LensSystem lens(test::libraryLens(name));
    const double h = 1e-3 * lens.frontApertureRadius();
    const double filmZ = lens.paraxial().rearFocalZ;
    int compared = 0;
    for (const GhostPath& g : ghostPaths(lens.prescription(), Coating::None)) {
      if (!g.focusFromFilmMm || std::abs(*g.focusFromFilmMm) > 1e4) continue;  // near afocal
      const auto out = lens.traceGhostFromScene({{h, 0.0, -1.0}, {0.0, 0.0, 1.0}}, g.first, g.second);
      ASSERT_TRUE(out) << g.first << "," << g.second;
      const double crossZ = out->origin.z - out->origin.x * out->direction.z / out->direction.x;
      const double want = filmZ + *g.focusFromFilmMm;
      EXPECT_NEAR(crossZ, want, 1e-3 * (std::abs(want - lens.rearZ()) + 1.0)) << g.first << "," << g.second;
      EXPECT_NEAR(out->transmittance, g.strength, 1e-4 * g.strength) << g.first << "," << g.second;
      ++compared;
    }
    EXPECT_GT(compared, 20);
  }
  // Out of range, or not second < first: nothing.
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  EXPECT_FALSE(lens.traceGhostFromScene({{1.0, 0.0, -1.0}, {0.0, 0.0, 1.0}}, 2, 5));
  EXPECT_FALSE(lens.traceGhostFromScene({{1.0, 0.0, -1.0}, {0.0, 0.0, 1.0}}, 99, 1));
}

}  // namespace
}  // namespace lensrt
