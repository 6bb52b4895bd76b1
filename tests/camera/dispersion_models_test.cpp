// The thin and thick lens derived from a lens with dispersion data: each
// sample's focal length is the lens's paraxial focal length at its
// wavelength, so the film is conjugate to a plane that moves with the
// wavelength by the lens equation 1/s = 1/f(l) - 1/v (axial colour).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "optics/chromatic.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

LensPrescription dgauss100() {
  return loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-100mm.lens");
}

// Where a camera ray (camera space, metres) crosses the axis: its z, and the
// distance from the axis there in x and y (both 0 when it crosses).
struct AxisCrossing {
  double z = 0, missX = 0, missY = 0;
};
AxisCrossing crossing(const Ray& r) {
  const double t = -double(r.origin.x) / double(r.direction.x);
  return {r.origin.z + t * r.direction.z, 0.0, r.origin.y + t * r.direction.y};
}

TEST(DispersionModels, FocalLengthRatioFollowsTheParaxialFocalLength) {
  const LensPrescription rx = dgauss100();
  const FocalLengthRatio ratio(rx);
  const double efl = computeParaxial(rx).efl;
  EXPECT_NEAR(ratio.at(kWavelengthDNm), 1.0, 1e-6);
  for (const double wl : {401.3, 486.1327, 550.0, 656.2725, 777.7}) {
    const double expected = computeParaxial(atWavelength(rx, wl)).efl / efl;
    EXPECT_NEAR(ratio.at(wl), expected, 2e-6) << wl;
  }
  // Undercorrected: blue focal length shorter than red.
  EXPECT_LT(ratio.at(450), ratio.at(650));
}

TEST(DispersionModels, ThinLensFocusesEachWavelengthWhereTheLensEquationSays) {
  const LensPrescription rx = dgauss100();
  ThinLensParams p;
  p.focalLengthMm = computeParaxial(rx).efl;
  p.fNumber = 2.0;
  p.focusMetres = 2.0;
  p.dispersion.emplace(rx);
  const FilmGeometry film{64, 64, 24.0, 24.0};
  const ThinLensCamera cam(Transform(), film, p);
  ASSERT_TRUE(cam.tracesWavelengths());
  EXPECT_TRUE(cam.info().dispersion);
  EXPECT_NE(cam.describe().find("dispersion=on"), std::string::npos);
  const double v = cam.imageDistanceMm();
  for (const double wl : {450.0, kWavelengthDNm, 650.0}) {
    CameraSample s;
    s.film = {32.0f, 32.0f};  // the film centre
    s.lens = {0.9f, 0.3f};
    s.wavelengthNm = float(wl);
    const auto r = cam.generateRay(s);
    ASSERT_TRUE(r);
    const double f = p.focalLengthMm * p.dispersion->at(s.wavelengthNm);
    const double sMm = 1.0 / (1.0 / f - 1.0 / v);
    const AxisCrossing c = crossing(r->ray);
    EXPECT_NEAR(c.z, -sMm * 1e-3, 2e-4 * sMm * 1e-3) << wl;
    EXPECT_NEAR(c.missY, 0.0, 1e-6) << wl;
  }
  // Without it every wavelength focuses at the focus distance.
  p.dispersion.reset();
  const ThinLensCamera plain(Transform(), film, p);
  EXPECT_FALSE(plain.tracesWavelengths());
  CameraSample s;
  s.film = {32.0f, 32.0f};
  s.lens = {0.9f, 0.3f};
  s.wavelengthNm = 450.0f;
  EXPECT_NEAR(crossing(plain.generateRay(s)->ray).z, -2.0, 1e-5);
}

TEST(DispersionModels, ThickLensFocusesEachWavelengthWhereTheLensEquationSays) {
  const LensPrescription rx = dgauss100();
  ThickLensParams p = thickLensFromParaxial(computeParaxial(rx), 2.0, 2.0);
  p.dispersion.emplace(rx);
  const FilmGeometry film{64, 64, 24.0, 24.0};
  const ThickLensCamera cam(Transform(), film, p);
  ASSERT_TRUE(cam.tracesWavelengths());
  const double v = cam.imageDistance();
  for (const double wl : {450.0, kWavelengthDNm, 650.0}) {
    CameraSample s;
    s.film = {32.0f, 32.0f};
    s.lens = {0.2f, 0.7f};
    s.wavelengthNm = float(wl);
    const auto r = cam.generateRay(s);
    ASSERT_TRUE(r);
    const double u = 1.0 / (1.0 / (p.focalLengthMm * p.dispersion->at(s.wavelengthNm)) - 1.0 / v);
    // The conjugate plane lies u in front of H; camera space starts at the entrance pupil.
    const double zMm = p.frontPrincipalZ - p.entrancePupilZ - u;
    EXPECT_NEAR(crossing(r->ray).z, zMm * 1e-3, 2e-4 * std::abs(zMm) * 1e-3) << wl;
    if (wl == kWavelengthDNm) {
      EXPECT_NEAR(crossing(r->ray).z, -2.0, 1e-3);
    }
  }
}

}  // namespace
}  // namespace lensrt
