// clippedShare: the share of pixels whose reading is at saturation in some
// channel, whichever comes first of the full well and the ADC's top. The
// exposures here are far from saturation either way (50 standard deviations
// of shot noise or more), so the expected shares are exact counts.
#include <gtest/gtest.h>

#include "sensor/readout.h"
#include "sensor/sensor_params.h"

namespace lensrt {
namespace {

// A 20 x 10 image of `value` in every channel, with `bright` at the listed
// channels of the first pixels (row by row).
Image image(float value, int pixels, int channel, float bright) {
  Image img(20, 10, {"R", "G", "B"});
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = value;
  for (int i = 0; i < pixels; ++i) img.at(i % 20, i / 20, channel) = bright;
  return img;
}

// The default sensor (full well 20000 e, 0.2 DN/e, 12 bits, black 64 DN),
// normalized: an image value of 1 fills the well. Half a well (10000 e, shot
// noise 100 e) never clips; three wells always do, in any one channel.
TEST(ClippedShare, CountsPixelsWithAnyChannelAtFullWell) {
  const SensorParams p;
  const SensorExposure e = normalizedSensorExposure(p, 0.01);
  for (int channel = 0; channel < 3; ++channel) {
    Image img = image(0.5f, 60, channel, 3.0f);
    applySensorReadout(img, p, e, 7);
    EXPECT_DOUBLE_EQ(clippedShare(img, p, e), 60.0 / 200.0) << "channel " << channel;
  }
  Image none = image(0.5f, 0, 0, 0.0f);
  applySensorReadout(none, p, e, 7);
  EXPECT_EQ(clippedShare(none, p, e), 0.0);
}

// At 4x analog gain (ISO 400 on a base of 100) the 12-bit ADC's top, 4095
// DN, is (4095 - 64) / 0.8 = 5039 e, before the 20000 e well: 6000 e clip
// there (shot noise 77 e), 2000 e do not.
TEST(ClippedShare, CountsPixelsAtTheAdcsTopBeforeTheWell) {
  const SensorParams p;
  SensorExposure e = normalizedSensorExposure(p, 0.01);
  e.analogGain = 4.0;
  Image img = image(0.1f, 45, 1, 0.3f);
  applySensorReadout(img, p, e, 7);
  EXPECT_DOUBLE_EQ(clippedShare(img, p, e), 45.0 / 200.0);
}

}  // namespace
}  // namespace lensrt
