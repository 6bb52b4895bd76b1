// The colour filter array: which colour each photosite of a raw file
// records, and the mosaic of digital numbers a raw file holds.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "sensor/readout.h"
#include "sensor/sensor_params.h"

namespace lensrt {

// A 2x2 pattern, row by row: RGGB is R G on even rows, G B on odd ones.
struct CfaPattern {
  std::array<int, 4> colours{0, 1, 1, 2};  // 0 R, 1 G, 2 B
  std::string name = "RGGB";
  int colourAt(int x, int y) const { return colours[(y & 1) * 2 + (x & 1)]; }
};

// "RGGB", "BGGR", "GRBG" or "GBRG"; nullopt otherwise.
std::optional<CfaPattern> parseCfaPattern(const std::string& name);

struct Mosaic {
  int width = 0, height = 0;
  std::vector<std::uint16_t> dn;  // row-major, one value per photosite
  double blackLevel = 0.0, whiteLevel = 0.0;
};

// Each photosite holds its CFA colour of `image`'s R, G, B. After a sensor's
// readout (applySensorReadout: R, G, B hold its readings in image units) that
// is the DN the reading came from, exactly (the float holds a DN of up to 16
// bits without loss); the white level is the DN of a full well, or the
// ADC's maximum. Without a sensor it is a 16-bit linear encoding: an image
// value of 1.0 is the white level 65535, 0 the black level 0. The pattern is
// placed by the frame (the image's origin), so a tile's mosaic is the frame's.
Mosaic makeMosaic(const Image& image, const CfaPattern& pattern, const SensorParams* sensor,
                  const SensorExposure* exposure);

}  // namespace lensrt
