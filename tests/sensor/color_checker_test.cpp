// The ColorChecker reflectances compiled in from data/colorchecker.csv.
#include "sensor/color_checker.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sensor/embedded_data.h"

namespace lensrt {
namespace {

TEST(ColorChecker, TwentyFourNamedPatchesOnOneGrid) {
  const auto& patches = colorCheckerPatches();
  EXPECT_EQ(patches.front().name, "dark-skin");
  EXPECT_EQ(patches[12].name, "blue");
  EXPECT_EQ(patches[18].name, "white-9.5");
  EXPECT_EQ(patches.back().name, "black-2");
  for (const ColorCheckerPatch& p : patches) {
    SCOPED_TRACE(p.name);
    EXPECT_EQ(p.wavelengthsNm.size(), 36u);
    EXPECT_EQ(p.wavelengthsNm.front(), 380.0);
    EXPECT_EQ(p.wavelengthsNm.back(), 730.0);
    ASSERT_EQ(p.reflectance.size(), p.wavelengthsNm.size());
    for (const double v : p.reflectance) {
      EXPECT_GT(v, 0.0);
      EXPECT_LT(v, 1.0);
    }
  }
}

TEST(ColorChecker, KnownValuesAndTheGreyScale) {
  const auto& patches = colorCheckerPatches();
  // BabelColor's average: dark skin at 380 nm, white 9.5 at 550 nm.
  EXPECT_EQ(patches[0].at(380.0), 0.055);
  EXPECT_NEAR(patches[0].at(385.0), (0.055 + 0.058) / 2, 1e-15);
  EXPECT_EQ(patches[18].at(550.0), patches[18].reflectance[17]);
  EXPECT_GT(patches[18].at(550.0), 0.85);
  EXPECT_EQ(patches[0].at(379.0), 0.0);
  // The neutral patches darken in order at every wavelength.
  for (std::size_t i = 0; i < patches[18].wavelengthsNm.size(); ++i)
    for (std::size_t p = 18; p < 23; ++p) EXPECT_GT(patches[p].reflectance[i], patches[p + 1].reflectance[i]);
  // Red reflects most at the long end, blue at the short end.
  EXPECT_GT(patches[14].at(650.0), 5 * patches[14].at(450.0));
  EXPECT_GT(patches[12].at(450.0), 5 * patches[12].at(650.0));
}

TEST(ColorChecker, EmbeddedDataEqualsTheDataFile) {
  std::ifstream in(std::filesystem::path(LENSRT_SOURCE_DIR) / "data/colorchecker.csv", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(embeddedColorChecker(), text.str());
}

}  // namespace
}  // namespace lensrt
