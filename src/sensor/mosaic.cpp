#include "sensor/mosaic.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lensrt {

std::optional<CfaPattern> parseCfaPattern(const std::string& name) {
  if (name.size() != 4) return std::nullopt;
  CfaPattern p;
  p.name = name;
  for (int i = 0; i < 4; ++i) {
    const char c = name[std::size_t(i)];
    p.colours[std::size_t(i)] = c == 'R' ? 0 : c == 'G' ? 1 : c == 'B' ? 2 : -1;
  }
  // One R, two G on a diagonal, one B: the four Bayer layouts.
  if (name != "RGGB" && name != "BGGR" && name != "GRBG" && name != "GBRG") return std::nullopt;
  return p;
}

Mosaic makeMosaic(const Image& image, const CfaPattern& pattern, const SensorParams* sensor,
                  const SensorExposure* exposure) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  if (r < 0 || g < 0 || b < 0) throw std::invalid_argument("a mosaic needs R, G and B");
  const int channel[3] = {r, g, b};
  Mosaic m;
  m.width = image.width;
  m.height = image.height;
  m.dn.resize(std::size_t(m.width) * std::size_t(m.height));
  if (sensor) {
    m.blackLevel = sensor->blackLevelDn;
    m.whiteLevel = std::min(
        sensor->maxDn(),
        std::round(sensor->blackLevelDn + sensor->fullWellE * sensor->gainDnPerE * exposure->analogGain));
  } else {
    m.blackLevel = 0.0;
    m.whiteLevel = 65535.0;
  }
  const double dnPerValue =
      sensor ? sensor->gainDnPerE * exposure->analogGain * exposure->electronsPerValue : 0.0;
  tbb::parallel_for(0, m.height, [&](int y) {
    for (int x = 0; x < m.width; ++x) {
      const int fx = image.originX + x, fy = image.originY + y, colour = pattern.colourAt(fx, fy);
      const double value = image.at(x, y, channel[colour]);
      const double dn =
          sensor ? std::clamp(
                       std::round(sensor->blackLevelDn + (std::isfinite(value) ? value : 0.0) * dnPerValue),
                       0.0, sensor->maxDn())
                 : std::round(std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0) * 65535.0);
      m.dn[std::size_t(y) * std::size_t(m.width) + std::size_t(x)] = std::uint16_t(dn);
    }
  });
  return m;
}

}  // namespace lensrt
