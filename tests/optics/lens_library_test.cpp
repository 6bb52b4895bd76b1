// Every library lens loads, and its traced focal length matches the one its
// file names (the designs' published values) within 2%.
#include <gtest/gtest.h>

#include <filesystem>
#include <utility>

#include "optics/lens_system.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

TEST(LensLibrary, EveryLensMatchesItsNominalFocalLength) {
  const auto files = listLenses(test::lensDir());
  ASSERT_GE(files.size(), 13u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const LensPrescription lens = loadLens(file);
    EXPECT_EQ(lens.name, file.stem().string());
    EXPECT_FALSE(lens.source.empty());
    ASSERT_GT(lens.nominalFocalLengthMm, 0.0);
    const LensSystem system(lens);
    EXPECT_NEAR(system.paraxial().efl / lens.nominalFocalLengthMm, 1.0, 0.02);
  }
}

TEST(LensLibrary, HasTheRequiredDesigns) {
  for (const char* name : {"dgauss-100mm", "dgauss-50mm", "wide-22mm", "telephoto-250mm", "fisheye-10mm",
                           "cooke-triplet-100mm", "tessar-100mm", "petzval-100mm"})
    EXPECT_NO_THROW(test::libraryLens(name)) << name;
  // The seed's design carries its Abbe numbers; five more designs do too.
  int withAbbe = 0;
  for (const auto& file : listLenses(test::lensDir())) {
    const LensPrescription lens = loadLens(file);
    bool all = true;
    for (const Surface& s : lens.surfaces)
      if (!s.medium.isAir() && s.medium.vd <= 0) all = false;
    withAbbe += all;
  }
  EXPECT_GE(withAbbe, 6);
  EXPECT_GT(test::libraryLens("dgauss-100mm").surfaces[0].medium.vd, 0.0);
}

}  // namespace
}  // namespace lensrt

namespace lensrt {
namespace {

// The pbrt-derived files carry the same numbers as pbrt's own (when the
// reference material is present).
TEST(LensLibrary, PbrtDesignsMatchTheReferenceFiles) {
  const std::filesystem::path shared = std::filesystem::path(LENSRT_SHARED_DIR) / "lenses";
  if (!std::filesystem::exists(shared)) GTEST_SKIP() << "reference lenses not present at " << shared;
  for (const auto& [ours, theirs] :
       {std::pair{"dgauss-50mm", "dgauss.50mm.dat"}, std::pair{"wide-22mm", "wide.22mm.dat"},
        std::pair{"telephoto-250mm", "telephoto.250mm.dat"}, std::pair{"fisheye-10mm", "fisheye.10mm.dat"}}) {
    SCOPED_TRACE(ours);
    const LensPrescription a = test::libraryLens(ours);
    const LensPrescription b = loadLens(shared / theirs);
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
      EXPECT_EQ(a.surfaces[i].radius, b.surfaces[i].radius);
      EXPECT_EQ(a.surfaces[i].thickness, b.surfaces[i].thickness);
      EXPECT_EQ(a.surfaces[i].medium.nd, b.surfaces[i].medium.nd);
      EXPECT_EQ(a.surfaces[i].apertureDiameter, b.surfaces[i].apertureDiameter);
    }
  }
  // The seed's table scaled by 0.5 is pbrt's 50 mm double Gauss.
  const LensPrescription seed = test::libraryLens("dgauss-100mm").scaled(0.5);
  const LensPrescription half = test::libraryLens("dgauss-50mm");
  for (std::size_t i = 0; i < seed.surfaces.size(); ++i) {
    EXPECT_NEAR(seed.surfaces[i].radius, half.surfaces[i].radius, 1e-9);
    EXPECT_NEAR(seed.surfaces[i].medium.nd, half.surfaces[i].medium.nd, 1e-9);
  }
}

}  // namespace
}  // namespace lensrt
