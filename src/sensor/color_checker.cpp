#include "sensor/color_checker.h"

#include <charconv>
#include <stdexcept>
#include <string_view>

#include "sensor/embedded_data.h"
#include "sensor/piecewise_linear.h"

namespace lensrt {
namespace {

std::vector<std::string_view> splitCommas(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

double toNumber(std::string_view field) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size())
    throw std::logic_error("data/colorchecker.csv: not a number");
  return v;
}

// The compiled-in table: `#` comments, a header of the patch names, then
// `wavelength_nm,patch 1,...,patch 24` rows. A malformed table is a build
// mistake (a test reads it), hence logic_error.
std::array<ColorCheckerPatch, kColorCheckerPatchCount> parseColorChecker(std::string_view text) {
  std::array<ColorCheckerPatch, kColorCheckerPatchCount> patches;
  bool header = true;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t newline = text.find('\n', start);
    const std::string_view line =
        text.substr(start, newline == std::string_view::npos ? newline : newline - start);
    start = newline == std::string_view::npos ? text.size() : newline + 1;
    if (line.empty() || line.starts_with('#')) continue;
    const std::vector<std::string_view> fields = splitCommas(line);
    if (fields.size() != kColorCheckerPatchCount + 1)
      throw std::logic_error("data/colorchecker.csv: expected 25 columns");
    for (std::size_t p = 0; p < kColorCheckerPatchCount; ++p) {
      if (header) {
        patches[p].name = std::string(fields[p + 1]);
      } else {
        patches[p].wavelengthsNm.push_back(toNumber(fields[0]));
        patches[p].reflectance.push_back(toNumber(fields[p + 1]));
      }
    }
    header = false;
  }
  return patches;
}

}  // namespace

double ColorCheckerPatch::at(double nm) const {
  return piecewiseLinear<double>(wavelengthsNm, reflectance, nm);
}

const std::array<ColorCheckerPatch, kColorCheckerPatchCount>& colorCheckerPatches() {
  static const std::array<ColorCheckerPatch, kColorCheckerPatchCount> patches =
      parseColorChecker(embeddedColorChecker());
  return patches;
}

}  // namespace lensrt
