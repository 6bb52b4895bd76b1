// `lensrt sensor list` with the spectral responses and `lensrt sensor plot`
// end to end: every camera listed with its range and peaks (text and JSON),
// plots of a camera, the CIE observer and a user's file, from a copy of the
// binary far from the repository (the data is compiled in), and one-line
// errors with the right exit status.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::readFile;
using cli::runLensrt;
using cli::runProgram;
using cli::RunResult;
using cli::TempDir;

const std::string kExample = std::string(LENSRT_TEST_DATA_DIR) + "/sensor/example-response.csv";

// The page coordinates of a polyline's points, by its id.
std::vector<std::pair<double, double>> polylinePoints(const std::string& svg, const std::string& id) {
  const std::size_t at = svg.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  const std::size_t start = svg.rfind("<polyline points=\"", at);
  const std::size_t begin = start + 18, end = svg.find('"', begin);
  std::vector<std::pair<double, double>> points;
  std::istringstream in(svg.substr(begin, end - begin));
  std::string pair;
  while (in >> pair) {
    const std::size_t comma = pair.find(',');
    points.emplace_back(std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1)));
  }
  return points;
}

TEST(SensorResponseCli, ListNamesEveryResponseWithRangeAndPeaks) {
  const RunResult text = runLensrt({"sensor", "list"});
  ASSERT_EQ(text.status, 0) << text.err;
  for (const char* line : {"cie1931 ", "canon-eos-5d-mark-ii", "Canon EOS 5D Mark II", "nikon-d850",
                           "Nikon D850", "sony-ilce-7rm3", "Sony ILCE-7RM3 (a7R III)", "380-720", "360-830"})
    EXPECT_NE(text.out.find(line), std::string::npos) << line;
  EXPECT_NE(text.out.find("default"), std::string::npos);  // the presets stay

  const RunResult json = runLensrt({"sensor", "list", "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  const nlohmann::json doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc.at("sensor_params").size(), 4u);
  const nlohmann::json& responses = doc.at("responses");
  ASSERT_GE(responses.size(), 11u);
  EXPECT_EQ(responses[0].at("name"), "cie1931");
  EXPECT_TRUE(responses[0].at("cie1931").get<bool>());
  for (std::size_t i = 1; i < responses.size(); ++i) {
    const nlohmann::json& r = responses[i];
    SCOPED_TRACE(r.dump());
    EXPECT_FALSE(r.at("cie1931").get<bool>());
    EXPECT_FALSE(r.at("maker").get<std::string>().empty());
    EXPECT_FALSE(r.at("model").get<std::string>().empty());
    EXPECT_EQ(r.at("min_nm"), 380.0);
    EXPECT_EQ(r.at("max_nm"), 720.0);
    const auto peak = r.at("peak_nm").get<std::vector<double>>();
    ASSERT_EQ(peak.size(), 3u);
    EXPECT_LT(peak[2], peak[1]);
    EXPECT_LT(peak[1], peak[0]);
  }
}

// A camera's three curves, normalised: the highest point of the three
// touches 1 on the axis; red peaks right of green, green right of blue.
TEST(SensorResponseCli, PlotsACameraFromACopyOfTheBinaryAnywhere) {
  const TempDir dir;
  // The binary alone, run from its own folder: the curves are compiled in.
  std::filesystem::copy_file(LENSRT_BINARY, dir / "lensrt");
  const RunResult r = runProgram((dir / "lensrt").string(),
                                 {"sensor", "plot", "nikon-d850", "-o", (dir / "d850.svg").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string wrote = "lensrt: wrote ";
  wrote.append((dir / "d850.svg").string()).append("\n");
  EXPECT_EQ(r.err, wrote);
  const std::string svg = readFile(dir / "d850.svg");
  EXPECT_NE(svg.find("Nikon D850"), std::string::npos);
  EXPECT_NE(svg.find("wavelength (nm)"), std::string::npos);
  double topY = 1e9;
  std::vector<double> peakX;
  for (const char* id : {"curve-r", "curve-g", "curve-b"}) {
    const auto points = polylinePoints(svg, id);
    ASSERT_EQ(points.size(), 35u) << id;  // 380-720 nm every 10 nm
    const auto top = std::min_element(points.begin(), points.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; });
    topY = std::min(topY, top->second);
    peakX.push_back(top->first);
  }
  EXPECT_GT(peakX[0], peakX[1]);
  EXPECT_GT(peakX[1], peakX[2]);
  EXPECT_NE(svg.find("class=\"r\""), std::string::npos);
  EXPECT_NE(svg.find("#c62828"), std::string::npos);
  // y = 1 is at 100 + 400 * (1 - 1 / 1.1) on the page.
  EXPECT_NEAR(topY, 100 + 400 * (1 - 1 / 1.1), 0.02);
}

TEST(SensorResponseCli, PlotsTheCieObserverAndAUsersFile) {
  const TempDir dir;
  const RunResult cie = runLensrt({"sensor", "plot", "cie1931", "-o", (dir / "cie.svg").string()});
  ASSERT_EQ(cie.status, 0) << cie.err;
  const std::string svg = readFile(dir / "cie.svg");
  EXPECT_EQ(polylinePoints(svg, "curve-g").size(), 471u);
  EXPECT_NE(svg.find("y\u0304 (peak 555 nm)"), std::string::npos);
  const RunResult mine = runLensrt({"sensor", "plot", kExample, "-o", (dir / "sub/mine.svg").string()});
  ASSERT_EQ(mine.status, 0) << mine.err;
  EXPECT_NE(mine.err.find("created folder"), std::string::npos) << mine.err;
  const std::string mineSvg = readFile(dir / "sub/mine.svg");
  EXPECT_NE(mineSvg.find("Example Three-band test camera"), std::string::npos);
  EXPECT_EQ(polylinePoints(mineSvg, "curve-b").size(), 8u);
}

TEST(SensorResponseCli, ErrorsAreOneLine) {
  const TempDir dir;
  const std::string out = (dir / "x.svg").string();
  std::string missing = "lensrt: error: ";
  missing.append((dir / "none.csv").string()).append(": no such response file");
  const struct {
    std::vector<std::string> args;
    int status;
    std::string start;  // the error line's beginning
  } cases[] = {
      {{"sensor", "plot", "nikon-d9000", "-o", out},
       1,
       "lensrt: error: unknown sensor response 'nikon-d9000'"},
      {{"sensor", "plot", (dir / "none.csv").string(), "-o", out}, 1, missing},
      {{"sensor", "plot", "nikon-d850", "-o", (dir / "x.png").string()},
       2,
       "lensrt: error: -o: sensor plot writes SVG"},
      {{"sensor", "plot", "nikon-d850"}, 2, "lensrt: error: "},
      {{"sensor", "plot", "-o", out}, 2, "lensrt: error: "},
      {{"sensor", "plot", "nikon-d850", "-o", out, "--bogus"}, 2, "lensrt: error: "},
      {{"sensor", "list", "--csv"}, 2, "lensrt: error: "},
  };
  for (const auto& c : cases) {
    const RunResult r = runLensrt(c.args);
    SCOPED_TRACE(r.err);
    EXPECT_EQ(r.status, c.status);
    EXPECT_EQ(r.err.rfind(c.start, 0), 0u);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace lensrt
