// The named responses: cie1931 and the measured cameras compiled in from
// data/sensor-responses, which must hold exactly the repository's files.
#include "sensor/sensor_response.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "color/cie.h"
#include "core/error.h"
#include "sensor/embedded_data.h"
#include "sensor/response_csv.h"

namespace lensrt {
namespace {

const std::filesystem::path kDataDir = std::filesystem::path(LENSRT_SOURCE_DIR) / "data/sensor-responses";

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> cameraNames() {
  std::vector<std::string> names = sensorResponseNames();
  names.erase(names.begin());
  return names;
}

TEST(SensorResponse, NamesCie1931FirstThenAtLeastTenCameras) {
  const std::vector<std::string> names = sensorResponseNames();
  ASSERT_GE(names.size(), 11u);
  EXPECT_EQ(names[0], "cie1931");
  const std::vector<std::string> cameras = cameraNames();
  EXPECT_TRUE(std::is_sorted(cameras.begin(), cameras.end()));
  for (const char* expected : {"canon-eos-5d-mark-ii", "nikon-d850", "sony-ilce-7rm3", "hasselblad-l1d-20c"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

// Every camera: three non-negative curves with some response each, peaking in
// the order of their colours, within 300-1100 nm, maker and model named.
TEST(SensorResponse, EveryCameraHasThreeCurvesPeakingBlueGreenRed) {
  for (const std::string& name : cameraNames()) {
    SCOPED_TRACE(name);
    const SensorResponse r = namedSensorResponse(name);
    EXPECT_EQ(r.name, name);
    EXPECT_FALSE(r.cie1931);
    EXPECT_FALSE(r.maker.empty());
    EXPECT_FALSE(r.model.empty());
    EXPECT_NE(r.source.find("PhysLight"), std::string::npos);
    ASSERT_GE(r.wavelengthsNm.size(), 3u);
    ASSERT_EQ(r.rgb.size(), r.wavelengthsNm.size());
    EXPECT_GE(r.wavelengthsNm.front(), 300.0);
    EXPECT_LE(r.wavelengthsNm.back(), 1100.0);
    Vec3d largest;
    for (const Vec3d& v : r.rgb)
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(v[c], 0.0);
        largest[c] = std::max(largest[c], v[c]);
      }
    for (int c = 0; c < 3; ++c) EXPECT_GT(largest[c], 0.1);
    const Vec3d peak = r.peakWavelengthsNm();
    EXPECT_LT(peak.z, peak.y);
    EXPECT_LT(peak.y, peak.x);
    EXPECT_GE(peak.z, 430.0);
    EXPECT_LE(peak.x, 640.0);
  }
}

// The compiled-in text is the repository's file byte for byte, and the files
// are exactly the named cameras.
TEST(SensorResponse, EmbeddedDataEqualsTheDataFiles) {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(kDataDir))
    if (entry.path().extension() == ".csv") files.insert(entry.path().stem().string());
  const std::vector<std::string> cameras = cameraNames();
  EXPECT_EQ(files, std::set<std::string>(cameras.begin(), cameras.end()));
  ASSERT_EQ(embeddedSensorResponses().size(), files.size());
  for (const EmbeddedFile& f : embeddedSensorResponses()) {
    SCOPED_TRACE(std::string(f.name));
    const std::filesystem::path file = kDataDir / (std::string(f.name) + ".csv");
    EXPECT_EQ(f.text, readFile(file));
    const SensorResponse embedded = namedSensorResponse(f.name), fromFile = readResponseCsv(file);
    EXPECT_EQ(embedded.wavelengthsNm, fromFile.wavelengthsNm);
    EXPECT_EQ(embedded.rgb, fromFile.rgb);
    EXPECT_EQ(embedded.maker, fromFile.maker);
    EXPECT_EQ(embedded.model, fromFile.model);
  }
}

// Values at known points of a data file: rows are exact, between rows linear.
TEST(SensorResponse, InterpolatesTheDataFile) {
  const SensorResponse d850 = namedSensorResponse("nikon-d850");
  EXPECT_EQ(d850.maker, "Nikon");
  EXPECT_EQ(d850.model, "D850");
  EXPECT_EQ(d850.wavelengthsNm.front(), 380.0);
  EXPECT_EQ(d850.wavelengthsNm.back(), 720.0);
  // nikon_d850_r/g/b at 380 nm as pbrt-v4 writes them.
  EXPECT_EQ(d850.at(380.0).x, 0.0013240464000000025);
  EXPECT_EQ(d850.at(380.0).y, 0.0012335690999999982);
  std::size_t i550 = 0;
  while (d850.wavelengthsNm[i550] != 550.0) ++i550;
  const Vec3d a = d850.rgb[i550], b = d850.rgb[i550 + 1];
  EXPECT_EQ(d850.at(550.0), a);
  const Vec3d mid = d850.at(552.5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid[c], 0.75 * a[c] + 0.25 * b[c], 1e-15);
  EXPECT_EQ(d850.at(379.0), Vec3d());
  EXPECT_EQ(d850.at(721.0), Vec3d());
}

TEST(SensorResponse, Cie1931IsTheObserver) {
  const SensorResponse cie = namedSensorResponse("cie1931");
  EXPECT_TRUE(cie.cie1931);
  EXPECT_EQ(cie.wavelengthsNm.front(), kCieMinNm);
  EXPECT_EQ(cie.wavelengthsNm.back(), kCieMaxNm);
  for (const double nm : {360.0, 445.0, 555.0, 555.25, 600.7, 830.0}) {
    const Vec3d expected = cieXyzMatching(nm), got = cie.at(nm);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-15) << nm;
  }
  EXPECT_EQ(cie.peakWavelengthsNm().y, 555.0);
}

TEST(SensorResponse, LoadsANameOrAFile) {
  EXPECT_EQ(loadSensorResponse("nikon-d810").model, "D810");
  const std::string example = std::string(LENSRT_TEST_DATA_DIR) + "/sensor/example-response.csv";
  EXPECT_EQ(loadSensorResponse(example).maker, "Example");
  // A path or a .csv ending is a file, whatever else it says.
  EXPECT_THROW(
      {
        try {
          loadSensorResponse("nikon-d810.CSV");
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(), "nikon-d810.CSV: no such response file");
          throw;
        }
      },
      InputError);
  EXPECT_THROW(loadSensorResponse("./nikon-d810"), InputError);
}

TEST(SensorResponse, UnknownNameListsTheKnownOnes) {
  try {
    namedSensorResponse("nikon-d9000");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find("unknown sensor response 'nikon-d9000' (known: cie1931, canon-eos-100d, "), 0u)
        << what;
    for (const std::string& name : sensorResponseNames())
      EXPECT_NE(what.find(name), std::string::npos) << name;
    EXPECT_NE(what.find("or a wavelength_nm,r,g,b .csv file)"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  // The name is echoed printable.
  try {
    loadSensorResponse("bad\nname");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("unknown sensor response 'bad?name'"), 0u) << e.what();
  }
}

}  // namespace
}  // namespace lensrt
