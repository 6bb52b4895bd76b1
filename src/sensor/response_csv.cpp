#include "sensor/response_csv.h"

#include <fmt/core.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/printable.h"

namespace lensrt {
namespace {

// Beyond silicon's response on both sides: a wavelength outside is a unit
// mistake (um, Angstrom) rather than a measurement.
constexpr double kMinNm = 300.0, kMaxNm = 1100.0;
constexpr std::size_t kMinRows = 3;
// Responses are relative, at any scale, but far below a double's range so
// that integrals of them stay finite.
constexpr double kMaxValue = 1e9;
constexpr std::size_t kMaxResponseFileBytes = 1 << 20;
constexpr std::array<std::string_view, 4> kColumns = {"wavelength_nm", "r", "g", "b"};

std::string_view trim(std::string_view s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// The whole field as a double (a leading '+' allowed, as spreadsheets write);
// nullopt when it is not a number.
std::optional<double> number(std::string_view field, bool& outOfRange) {
  if (field.size() > 1 && field[0] == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  outOfRange = ec == std::errc::result_out_of_range;
  if (ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

// `# key: value` comments describe the camera; the first of each key counts.
void readMetadata(std::string_view comment, SensorResponse& response) {
  const std::pair<std::string_view, std::string*> keys[] = {
      {"maker:", &response.maker}, {"model:", &response.model}, {"source:", &response.source}};
  for (const auto& [key, field] : keys)
    if (comment.starts_with(key) && field->empty()) *field = printable(trim(comment.substr(key.size())), 200);
}

}  // namespace

SensorResponse parseResponseCsv(std::string_view text, const std::string& file) {
  SensorResponse response;
  response.name = file;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a spreadsheet's UTF-8 byte order mark
  bool headerAllowed = true;
  int lineNumber = 0;
  for (std::size_t start = 0; start < text.size(); ++lineNumber) {
    const std::size_t newline = text.find('\n', start);
    std::string_view line = text.substr(start, newline == std::string_view::npos ? newline : newline - start);
    start = newline == std::string_view::npos ? text.size() : newline + 1;
    const int at = lineNumber + 1;
    if (const std::string_view t = trim(line); t.starts_with('#')) readMetadata(trim(t.substr(1)), response);
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    const std::vector<std::string_view> fields = splitFields(line);
    if (fields.size() != kColumns.size())
      throw InputError(
          file,
          fmt::format("expected 4 comma-separated columns (wavelength_nm,r,g,b), got {}", fields.size()), at);
    std::array<double, 4> values{};
    std::size_t numbers = 0;
    std::optional<std::size_t> firstBad;
    bool badOutOfRange = false;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      bool outOfRange = false;
      if (const std::optional<double> v = number(fields[i], outOfRange)) {
        values[i] = *v;
        ++numbers;
      } else if (!firstBad) {
        firstBad = i;
        badOutOfRange = outOfRange;
      }
    }
    // A first line without a single number names the columns.
    const bool header = headerAllowed && numbers == 0;
    headerAllowed = false;
    if (header) continue;
    if (firstBad) {
      const std::string_view field = fields[*firstBad];
      const std::string_view column = kColumns[*firstBad];
      if (field.empty()) throw InputError(file, fmt::format("column {} is empty", column), at);
      throw InputError(file,
                       fmt::format("column {}: '{}' is {}", column, printable(field),
                                   badOutOfRange ? "beyond the range of a double" : "not a number"),
                       at);
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (std::isnan(values[i])) throw InputError(file, fmt::format("column {} is NaN", kColumns[i]), at);
      if (std::isinf(values[i]))
        throw InputError(file, fmt::format("column {} is infinite", kColumns[i]), at);
    }
    const double nm = values[0];
    if (nm < kMinNm || nm > kMaxNm)
      throw InputError(
          file,
          fmt::format(
              "wavelength {:g} nm is outside {:g}-{:g} nm{}", nm, kMinNm, kMaxNm,
              nm >= kMinNm / 1000 && nm <= kMaxNm / 1000 ? " (micrometres? the first column is in nm)" : ""),
          at);
    if (!response.wavelengthsNm.empty() && nm <= response.wavelengthsNm.back())
      throw InputError(file,
                       fmt::format("wavelength {:g} nm does not increase on the row before ({:g} nm): "
                                   "wavelengths must strictly increase",
                                   nm, response.wavelengthsNm.back()),
                       at);
    for (std::size_t i = 1; i < values.size(); ++i) {
      if (values[i] < 0.0)
        throw InputError(
            file,
            fmt::format("column {} is negative ({:g}): responses are at least 0", kColumns[i], values[i]),
            at);
      if (values[i] > kMaxValue)
        throw InputError(file,
                         fmt::format("column {} is too large ({:g}): responses are relative, at most {:g}",
                                     kColumns[i], values[i], kMaxValue),
                         at);
    }
    response.wavelengthsNm.push_back(nm);
    response.rgb.push_back({values[1], values[2], values[3]});
  }
  if (response.wavelengthsNm.size() < kMinRows)
    throw InputError(
        file, fmt::format("{} rows of wavelength_nm,r,g,b; a response needs at least {}",
                          response.wavelengthsNm.empty() ? std::string("no")
                                                         : std::to_string(response.wavelengthsNm.size()),
                          kMinRows));
  for (std::size_t c = 0; c < 3; ++c) {
    bool any = false;
    for (const Vec3d& v : response.rgb) any = any || v[c] > 0.0;
    if (!any) throw InputError(file, fmt::format("column {} is 0 at every wavelength", kColumns[c + 1]));
  }
  return response;
}

SensorResponse readResponseCsv(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(name, "no such response file");
  if (std::filesystem::file_size(file, ec) > kMaxResponseFileBytes)
    throw InputError(name, "too large for a response file (over 1 MiB)");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw InputError(name, "cannot read");
  return parseResponseCsv(text.str(), name);
}

}  // namespace lensrt
