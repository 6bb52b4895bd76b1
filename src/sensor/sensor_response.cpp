#include "sensor/sensor_response.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "color/cie.h"
#include "core/ascii_lower.h"
#include "core/error.h"
#include "core/printable.h"
#include "sensor/embedded_data.h"
#include "sensor/piecewise_linear.h"
#include "sensor/response_csv.h"

namespace lensrt {
namespace {

// The observer's own 1 nm table, so that at() is cieXyzMatching exactly.
SensorResponse cie1931Response() {
  SensorResponse r;
  r.name = std::string(kCie1931Response);
  r.source = "CIE 1931 2-degree standard observer";
  r.cie1931 = true;
  for (double nm = kCieMinNm; nm <= kCieMaxNm; nm += 1.0) {
    r.wavelengthsNm.push_back(nm);
    r.rgb.push_back(cieXyzMatching(nm));
  }
  return r;
}

bool endsWithCsv(std::string_view s) {
  return s.size() >= 4 && asciiLower(s.substr(s.size() - 4)) == ".csv";
}

}  // namespace

Vec3d SensorResponse::at(double nm) const {
  return piecewiseLinear<Vec3d>(wavelengthsNm, rgb, nm);
}

Vec3d SensorResponse::peakWavelengthsNm() const {
  Vec3d peak, largest(-1.0, -1.0, -1.0);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      if (rgb[i][c] > largest[c]) {
        largest[c] = rgb[i][c];
        peak[c] = wavelengthsNm[i];
      }
  return peak;
}

std::vector<std::string> sensorResponseNames() {
  std::vector<std::string> names{std::string(kCie1931Response)};
  for (const EmbeddedFile& f : embeddedSensorResponses()) names.emplace_back(f.name);
  return names;
}

SensorResponse namedSensorResponse(std::string_view name) {
  if (name == kCie1931Response) return cie1931Response();
  for (const EmbeddedFile& f : embeddedSensorResponses())
    if (f.name == name) {
      SensorResponse r = parseResponseCsv(f.text, fmt::format("data/sensor-responses/{}.csv", f.name));
      r.name = std::string(f.name);
      return r;
    }
  std::string known;
  for (const std::string& n : sensorResponseNames()) known.append(known.empty() ? "" : ", ").append(n);
  throw InputError("",
                   fmt::format("unknown sensor response '{}' (known: {}; or a wavelength_nm,r,g,b .csv file)",
                               printable(name), known));
}

SensorResponse loadSensorResponse(std::string_view nameOrFile) {
  if (endsWithCsv(nameOrFile) || nameOrFile.find_first_of("/\\") != std::string_view::npos)
    return readResponseCsv(std::filesystem::path(nameOrFile));
  return namedSensorResponse(nameOrFile);
}

}  // namespace lensrt
