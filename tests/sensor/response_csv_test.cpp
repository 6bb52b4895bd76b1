// The response file reader: rows at any spacing, interpolated linearly, and
// one error line naming the file, line and problem for each kind of bad file.
#include "sensor/response_csv.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace lensrt {
namespace {

const std::filesystem::path kExample =
    std::filesystem::path(LENSRT_TEST_DATA_DIR) / "sensor/example-response.csv";

// The error a text makes, "" when it parses.
std::string errorOf(const std::string& text) {
  try {
    parseResponseCsv(text, "r.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResponseCsv, ReadsRowsAtAnySpacingWithHeaderAndComments) {
  const SensorResponse r = readResponseCsv(kExample);
  EXPECT_EQ(r.name, kExample.string());
  EXPECT_EQ(r.maker, "Example");
  EXPECT_EQ(r.model, "Three-band test camera");
  EXPECT_FALSE(r.cie1931);
  const std::vector<double> nm = {400, 425, 450, 500, 550, 600, 650, 700};
  EXPECT_EQ(r.wavelengthsNm, nm);
  ASSERT_EQ(r.rgb.size(), nm.size());
  EXPECT_EQ(r.rgb[4], Vec3d(0.20, 1.00, 0.05));
  EXPECT_EQ(r.peakWavelengthsNm(), Vec3d(600, 550, 450));
}

TEST(ResponseCsv, InterpolatesLinearlyAndIsZeroOutside) {
  const SensorResponse r = readResponseCsv(kExample);
  // Exactly the samples at tabulated wavelengths, both ends included.
  EXPECT_EQ(r.at(400), Vec3d(0.00, 0.02, 0.30));
  EXPECT_EQ(r.at(700), Vec3d(0.10, 0.01, 0.00));
  EXPECT_EQ(r.at(550), Vec3d(0.20, 1.00, 0.05));
  // Between rows 25 nm apart and 50 nm apart.
  const Vec3d a = r.at(412.5), b = r.at(510);
  EXPECT_NEAR(a.z, 0.55, 1e-12);
  EXPECT_NEAR(a.y, 0.035, 1e-12);
  EXPECT_NEAR(b.x, 0.05 + 0.2 * (0.20 - 0.05), 1e-12);
  EXPECT_NEAR(b.y, 0.60 + 0.2 * (1.00 - 0.60), 1e-12);
  EXPECT_NEAR(b.z, 0.40 + 0.2 * (0.05 - 0.40), 1e-12);
  EXPECT_EQ(r.at(399.999), Vec3d());
  EXPECT_EQ(r.at(700.001), Vec3d());
  EXPECT_EQ(r.at(std::nan("")), Vec3d());
}

TEST(ResponseCsv, AcceptsWhatSpreadsheetsWrite) {
  // No header, CRLF line ends, a byte order mark, spaces, '+' signs, an
  // exponent, trailing comments and blank lines.
  const SensorResponse r = parseResponseCsv(
      "\xEF\xBB\xBF"
      "# source: a spreadsheet\r\n380, 1e-3, +0.5 ,0\r\n\r\n390,0.1,0.2,0.3  # peak\r\n400,0,0,1\r\n",
      "s.csv");
  EXPECT_EQ(r.source, "a spreadsheet");
  EXPECT_EQ(r.wavelengthsNm, (std::vector<double>{380, 390, 400}));
  EXPECT_EQ(r.rgb[0], Vec3d(1e-3, 0.5, 0.0));
  EXPECT_EQ(r.rgb[2], Vec3d(0, 0, 1));
}

TEST(ResponseCsv, EachProblemIsOneLineNamingFileAndLine) {
  const std::string header = "wavelength_nm,r,g,b\n";
  std::string longFieldError = "r.csv:2: column b: '";
  longFieldError.append(40, 'x').append("...' is not a number");
  const struct {
    std::string text, error;
  } cases[] = {
      {header + "400,0.1,nan,0.1\n410,1,1,1\n420,1,1,1\n", "r.csv:2: column g is NaN"},
      {header + "400,0.1,0.2,-0.01\n410,1,1,1\n420,1,1,1\n",
       "r.csv:2: column b is negative (-0.01): responses are at least 0"},
      {header + "400,1,1,1\n410,1,1,1\n405,1,1,1\n",
       "r.csv:4: wavelength 405 nm does not increase on the row before (410 nm): wavelengths must strictly "
       "increase"},
      {header + "400,1,1,1\n400,1,1,1\n410,1,1,1\n",
       "r.csv:3: wavelength 400 nm does not increase on the row before (400 nm): wavelengths must strictly "
       "increase"},
      {header + "400,1,1,1\n410,1,1,1\n",
       "r.csv: 2 rows of wavelength_nm,r,g,b; a response needs at least 3"},
      {header, "r.csv: no rows of wavelength_nm,r,g,b; a response needs at least 3"},
      {"", "r.csv: no rows of wavelength_nm,r,g,b; a response needs at least 3"},
      {header + "0.4,1,1,1\n0.5,1,1,1\n0.6,1,1,1\n",
       "r.csv:2: wavelength 0.4 nm is outside 300-1100 nm (micrometres? the first column is in nm)"},
      {header + "1000,1,1,1\n1100,1,1,1\n1200,1,1,1\n", "r.csv:4: wavelength 1200 nm is outside 300-1100 nm"},
      {header + "400,1,1\n", "r.csv:2: expected 4 comma-separated columns (wavelength_nm,r,g,b), got 3"},
      {header + "400,1,1,1,1\n", "r.csv:2: expected 4 comma-separated columns (wavelength_nm,r,g,b), got 5"},
      {"nm;r;g;b\n", "r.csv:1: expected 4 comma-separated columns (wavelength_nm,r,g,b), got 1"},
      {header + "400,1,1,1\n410,0.5x,1,1\n", "r.csv:3: column r: '0.5x' is not a number"},
      {header + "4OO,1,1,1\n", "r.csv:2: column wavelength_nm: '4OO' is not a number"},
      {header + "400,1,,1\n", "r.csv:2: column g is empty"},
      {header + "400,1,1,1e999\n", "r.csv:2: column b: '1e999' is beyond the range of a double"},
      {header + "400,inf,1,1\n", "r.csv:2: column r is infinite"},
      {header + "400,1,2e9,1\n",
       "r.csv:2: column g is too large (2e+09): responses are relative, at most 1e+09"},
      {header + "nan,1,1,1\n", "r.csv:2: column wavelength_nm is NaN"},
      {header + header, "r.csv:2: column wavelength_nm: 'wavelength_nm' is not a number"},
      {header + "400,0,1,1\n410,0,1,1\n420,0,1,1\n", "r.csv: column r is 0 at every wavelength"},
      // A field echoed is cut short and printable, so the message stays one line.
      {header + "400,1,1," + std::string(100, 'x') + "\n", longFieldError},
      {header + "400,1,1,\x01x\n", "r.csv:2: column b: '?x' is not a number"},
  };
  for (const auto& c : cases) EXPECT_EQ(errorOf(c.text), c.error) << c.text;
}

TEST(ResponseCsv, FileProblems) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "lensrt-response-csv-";
  dir += std::to_string(getpid());
  std::filesystem::create_directories(dir);
  const auto errorOfFile = [](const std::filesystem::path& file) -> std::string {
    try {
      readResponseCsv(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(errorOfFile(dir / "missing.csv"), (dir / "missing.csv").string() + ": no such response file");
  EXPECT_EQ(errorOfFile(dir), dir.string() + ": no such response file");
  {
    std::ofstream big(dir / "big.csv");
    big << std::string((1 << 20) + 1, '#');
  }
  EXPECT_EQ(errorOfFile(dir / "big.csv"),
            (dir / "big.csv").string() + ": too large for a response file (over 1 MiB)");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lensrt
