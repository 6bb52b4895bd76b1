// The closest focus every camera model keeps to: magnification 1:1 unless the
// lens file states its own, never nearer than a real image allows.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "optics/focus.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

// The Gaussian lens equation at 1:1: the object 2f in front of the front
// principal plane images 2f behind the rear one, at magnification -1.
TEST(ClosestFocus, IsMagnificationOneToOneWithoutAStatedLimit) {
  for (const char* name : {"dgauss-50mm", "dgauss-100mm", "telephoto-250mm", "wide-22mm"}) {
    SCOPED_TRACE(name);
    const LensSystem lens(test::libraryLens(name));
    const ParaxialData& p = lens.paraxial();
    const double closest = closestFocusDistanceMm(lens);
    const Conjugate c = paraxialConjugate(p, closest);
    EXPECT_NEAR(c.magnification, -1.0, 1e-9);
    EXPECT_NEAR(c.objectDistanceFromH, 2 * p.efl, 1e-9 * p.efl);
    EXPECT_NEAR(c.imageDistance, 2 * p.efl, 1e-9 * p.efl);
    EXPECT_GT(closest, nearestRealImageDistanceMm(lens));
  }
}

TEST(ClosestFocus, ALensFileMayStateItsOwn) {
  const auto dir = std::filesystem::temp_directory_path() / "lensrt_closest_focus_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "macro.json";
  std::ofstream(file) << R"({"format":"lensrt-lens","version":1,"name":"m","description":"","source":"",)"
                         R"("closest_focus_m":0.45,"surfaces":[)"
                         R"({"radius":0,"thickness":2,"aperture":10,"stop":true},)"
                         R"({"radius":51.68,"thickness":5,"aperture":20,"nd":1.5168,"vd":64.17},)"
                         R"({"radius":-51.68,"thickness":48,"aperture":20}]})";
  const LensPrescription stated = loadLens(file);
  EXPECT_DOUBLE_EQ(stated.closestFocusMm, 450.0);
  EXPECT_DOUBLE_EQ(closestFocusDistanceMm(LensSystem(stated)), 450.0);
  // Scaling the design scales its limit.
  EXPECT_DOUBLE_EQ(stated.scaled(2.0).closestFocusMm, 900.0);
  // A stated limit nearer than any real image is not believed.
  LensPrescription tooNear = stated;
  tooNear.closestFocusMm = 1.0;
  const LensSystem near(tooNear);
  EXPECT_DOUBLE_EQ(closestFocusDistanceMm(near), nearestRealImageDistanceMm(near));
  std::ofstream(file) << R"({"format":"lensrt-lens","version":1,"name":"m","description":"","source":"",)"
                         R"("closest_focus_m":-1,"surfaces":[]})";
  EXPECT_THROW(loadLens(file), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lensrt
