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

// Each photosite reads its CFA colour of `image`'s R, G, B. With a sensor
// (--noise on) it is that sensor's readout of the noiseless value (the same
// numbers as the image's channels got, for the colour a site records); the
// white level is the DN of a full well, or the ADC's maximum. Without one
// it is a 16-bit linear encoding: an image value of 1.0 is the white level
// 65535, 0 the black level 0. `noiseless` names the channels to read:
// "noiseless." after a readout, "" otherwise. (frameX, frameY) of the image's
// pixels come from its origin, so a tile's mosaic is the frame's.
Mosaic makeMosaic(const Image& image, const CfaPattern& pattern, const SensorParams* sensor,
                  const SensorExposure* exposure, std::uint64_t seed, const std::string& noiseless);

}  // namespace lensrt
