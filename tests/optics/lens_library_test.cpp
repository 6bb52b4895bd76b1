// Every library lens loads, and its traced focal length matches the one its
// file names (the designs' published values) within 2%.
#include <gtest/gtest.h>

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
