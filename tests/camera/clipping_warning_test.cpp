// readOut's clipping warning: said once when more than 5% of the pixels read
// out at saturation (kClippedShareToWarn), with the share and the pixel
// pitch; silent at 5% and below. The images hold values far from saturation
// either way (half a well, 100 standard deviations of shot noise below it,
// or three wells), so the clipped counts are exact.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "api/sensor_readout.h"

namespace lensrt {
namespace {

// A 20 x 10 film on an 8 x 4 mm sensor: 400 um pixels. The default sensor
// (20000 e full well), normalized: an image value of 1 fills the well.
SensorReadout readout() {
  SensorSpec spec;
  spec.noise = true;
  return *sensorReadout(spec, Exposure{}, FilmGeometry{20, 10, 8, 4}, std::nullopt);
}

// The warnings of reading out 200 pixels of half a well, `clipped` of them
// with three wells in G.
std::vector<std::string> warningsFor(int clipped) {
  Image img(20, 10, {"R", "G", "B"});
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = c == 1 && y * img.width + x < clipped ? 3.0f : 0.5f;
  std::vector<std::string> said;
  Warnings warnings([&](const std::string& w) { said.push_back(w); });
  ImageMetadata metadata;
  readOut(readout(), img, metadata, 7, warnings);
  return said;
}

TEST(ClippingWarning, SilentUpToFivePercentOfThePixels) {
  EXPECT_EQ(readout().pixelPitchUm, 400.0);
  for (const int clipped : {0, 1, 6, 10}) EXPECT_TRUE(warningsFor(clipped).empty()) << clipped << " of 200";
}

TEST(ClippingWarning, OneLineWithTheShareAndThePitchAboveFivePercent) {
  for (const auto& [clipped, share] :
       std::vector<std::pair<int, std::string>>{{12, "6%"}, {50, "25%"}, {200, "100%"}}) {
    SCOPED_TRACE(clipped);
    const std::vector<std::string> said = warningsFor(clipped);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said[0].find('\n'), std::string::npos) << said[0];
    for (const std::string& part :
         {share + " of the pixels clip at the sensor's full well (20000 e)", std::string("(400 um)")})
      EXPECT_NE(said[0].find(part), std::string::npos) << part << "\n" << said[0];
  }
}

}  // namespace
}  // namespace lensrt
