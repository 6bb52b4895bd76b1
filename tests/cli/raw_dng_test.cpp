// lensrt render --raw OUT.dng: the raw file developers read (dcraw decodes
// nothing under 22 x 22, hence 33 x 23: odd, so the pattern wraps). Debian's own
// raw developers check it: dcraw and LibRaw's raw-identify identify the
// camera, size and pattern; `dcraw -D -4 -T` returns exactly the mosaic lensrt
// wrote; a grey card developed with `dcraw -w -o 1 -4 -T` (and, for the
// photon-counted cameras, darktable-cli and rawtherapee-cli) comes out neutral.
#include <gtest/gtest.h>
#include <tiffio.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/cli_util.h"
#include "color/cie.h"
#include "color/illuminant.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::runProgram;
using cli::RunResult;
using cli::TempDir;

const std::string kScene = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";

bool haveDevelopers() {
  return runProgram("sh", {"-c", "command -v dcraw && command -v raw-identify"}).status == 0;
}

struct Tiff {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint16_t> values;  // row-major, interleaved
  std::uint16_t at(int x, int y, int c = 0) const {
    return values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
                  std::size_t(c)];
  }
};

// A 16-bit TIFF as dcraw writes it (one strip per row or more, contiguous).
Tiff readTiff(const std::filesystem::path& file) {
  // darktable's TIFFs carry tags libtiff does not know, each a warning line.
  TIFFSetWarningHandler(nullptr);
  struct Closer {
    void operator()(TIFF* t) const { TIFFClose(t); }
  };
  const std::unique_ptr<TIFF, Closer> tiff(TIFFOpen(file.c_str(), "r"));
  EXPECT_TRUE(tiff) << file;
  Tiff out;
  if (!tiff) return out;
  std::uint32_t w = 0, h = 0;
  std::uint16_t spp = 1, bits = 0;
  TIFFGetField(tiff.get(), TIFFTAG_IMAGEWIDTH, &w);
  TIFFGetField(tiff.get(), TIFFTAG_IMAGELENGTH, &h);
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_SAMPLESPERPIXEL, &spp);
  TIFFGetField(tiff.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  EXPECT_EQ(bits, 16);
  out.width = int(w), out.height = int(h), out.channels = spp;
  out.values.resize(std::size_t(w) * h * spp);
  for (std::uint32_t y = 0; y < h; ++y)
    TIFFReadScanline(tiff.get(), &out.values[std::size_t(y) * w * spp], y, 0);
  return out;
}

RunResult render(const TempDir& dir, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render",
                                   kScene,
                                   "--res",
                                   "33x23",
                                   "--spp",
                                   "2",
                                   "-q",
                                   "-o",
                                   (dir / "a.exr").string(),
                                   "--raw",
                                   (dir / "a.dng").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return runLensrt(args);
}

TEST(RawDng, DcrawAndLibRawIdentifyTheCamera) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw or raw-identify not installed (tools/setup installs them)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "4", "--exposure",
                         "physical", "--shutter", "1/250", "--iso", "400"})
                .status,
            0);
  const RunResult d = runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  for (const char* line :
       {"Camera: lensrt lens dgauss-50mm", "ISO speed: 400", "Shutter: 1/250.0 sec", "Aperture: f/4.0",
        "Image size:    33 x 23", "Filter pattern: RG/GB", "DNG Version: 1.4"})
    EXPECT_NE(d.out.find(line), std::string::npos) << line << "\n" << d.out;
  const RunResult l = runProgram("raw-identify", {"-v", (dir / "a.dng").string()});
  ASSERT_EQ(l.status, 0) << l.err;
  for (const char* line : {"Camera: lensrt lens dgauss-50mm", "ISO speed: 400", "Image size:    33 x 23",
                           "Filter pattern: RGGBRGGB"})
    EXPECT_NE(l.out.find(line), std::string::npos) << line << "\n" << l.out;
  ASSERT_EQ(render(dir, {"--cfa", "GBRG"}).status, 0);
  EXPECT_NE(runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()}).out.find("Filter pattern: GB/RG"),
            std::string::npos);
}

// The EXIF a photo's tools read: the lens, the 35 mm-equivalent focal length
// (f times 43.27 mm over the sensor's diagonal), the focal plane's pixels per
// cm, the capture time (SOURCE_DATE_EPOCH's when set), and a camera
// response's maker and model as Make and Model.
TEST(RawDng, ExifNamesTheLensTheFocalPlaneAndTheCamera) {
  const TempDir dir;
  ::setenv("SOURCE_DATE_EPOCH", "86400", 1);
  const RunResult r = render(dir, {"--camera", "lens", "--lens", "dgauss-50mm", "--sensor-response",
                                   "canon-eos-5d-mark-ii", "--sensor", "aps-c"});
  ::unsetenv("SOURCE_DATE_EPOCH");
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  readImage(dir / "a.exr", &meta);
  const double focal = std::stod(meta["lensrt:focal_length_mm"]);
  double sensorW = 0, sensorH = 0;
  ASSERT_EQ(std::sscanf(meta["lensrt:sensor_mm"].c_str(), "%lfx%lf", &sensorW, &sensorH), 2);

  struct Closer {
    void operator()(TIFF* t) const { TIFFClose(t); }
  };
  const std::unique_ptr<TIFF, Closer> tiff(TIFFOpen((dir / "a.dng").c_str(), "r"));
  ASSERT_TRUE(tiff);
  char* make = nullptr;
  char* model = nullptr;
  ASSERT_TRUE(TIFFGetField(tiff.get(), TIFFTAG_MAKE, &make));
  ASSERT_TRUE(TIFFGetField(tiff.get(), TIFFTAG_MODEL, &model));
  EXPECT_STREQ(make, "Canon");
  EXPECT_STREQ(model, "EOS 5D Mark II");
  toff_t exif = 0;
  ASSERT_TRUE(TIFFGetField(tiff.get(), TIFFTAG_EXIFIFD, &exif));
  ASSERT_TRUE(TIFFReadEXIFDirectory(tiff.get(), exif));
  char* lens = nullptr;
  ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_LENSMODEL, &lens));
  EXPECT_STREQ(lens, "dgauss-50mm");
  std::uint16_t f35 = 0;
  ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALLENGTHIN35MMFILM, &f35));
  EXPECT_EQ(f35, std::lround(focal * std::hypot(36.0, 24.0) / std::hypot(sensorW, sensorH)));
  EXPECT_GT(f35, focal * 1.4);  // an APS-C sensor crops by about 1.5
  float perCm = 0;
  std::uint16_t unit = 0;
  ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALPLANEXRESOLUTION, &perCm));
  ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_FOCALPLANERESOLUTIONUNIT, &unit));
  EXPECT_EQ(unit, 3);  // centimetres
  EXPECT_NEAR(perCm, 33 / (sensorW / 10), 1e-3 * perCm);
  char* when = nullptr;
  ASSERT_TRUE(TIFFGetField(tiff.get(), EXIFTAG_DATETIMEORIGINAL, &when));
  EXPECT_STREQ(when, "1970:01:02 00:00:00");
}

// Each site holds its colour's value of the EXR: v * 65535 (noiseless), or
// with --noise on the DN the EXR's reading of that colour came from.
void expectMosaicOf(const TempDir& dir, const std::string& pattern, bool noise) {
  const RunResult d = runProgram("dcraw", {"-D", "-4", "-T", (dir / "a.dng").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  const Tiff raw = readTiff(dir / "a.tiff");
  ImageMetadata meta;
  const Image img = readImage(dir / "a.exr", &meta);
  ASSERT_EQ(raw.width, img.width);
  ASSERT_EQ(raw.height, img.height);
  const double perValue = noise ? std::stod(meta["lensrt:sensor_electrons_per_value"]) *
                                      std::stod(meta["lensrt:sensor_dn_per_electron"])
                                : 65535.0;
  const double black = noise ? 64.0 : 0.0;  // the default sensor's black level
  int mismatches = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const char colour = pattern[std::size_t((y & 1) * 2 + (x & 1))];
      const double v = img.at(x, y, img.channelIndex(std::string(1, colour)));
      const double expected =
          noise ? std::round(black + v * perValue) : std::round(std::clamp(v, 0.0, 1.0) * 65535);
      mismatches += raw.at(x, y) != std::uint16_t(expected);
    }
  EXPECT_EQ(mismatches, 0);
}

TEST(RawDng, DcrawReturnsTheMosaicLensrtWrote) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--cfa", "GRBG"}).status, 0);
  expectMosaicOf(dir, "GRBG", false);
  ASSERT_EQ(render(dir, {"--noise", "on"}).status, 0);
  expectMosaicOf(dir, "RGGB", true);
}

// A crop starting on an odd row and column: the file declares the pattern as
// seen from its first pixel (the frame's RGGB is BGGR... from (1, 1)).
TEST(RawDng, ACropDeclaresItsOwnPhaseOfThePattern) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--crop", "1,30,1,23"}).status, 0);
  const RunResult d = runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()});
  EXPECT_NE(d.out.find("Filter pattern: BG/GR"), std::string::npos) << d.out;
  expectMosaicOf(dir, "BGGR", false);
}

// The linear value of a 16-bit sRGB-encoded one (IEC 61966-2-1's curve).
double srgbToLinear(std::uint16_t encoded) {
  const double v = encoded / 65535.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// A developed grey card (linear RGB, or sRGB-encoded with `srgbEncoded`): R,
// G and B each within `tolerance` of their mean over the frame (a 4-pixel
// border, where demosaicing guesses, left out).
void expectNeutral(const std::filesystem::path& developed, double tolerance, bool srgbEncoded = false) {
  const Tiff rgb = readTiff(developed);
  ASSERT_EQ(rgb.channels, 3) << developed;
  double sum[3] = {0, 0, 0};
  for (int y = 4; y < rgb.height - 4; ++y)
    for (int x = 4; x < rgb.width - 4; ++x)
      for (int c = 0; c < 3; ++c) sum[c] += srgbEncoded ? srgbToLinear(rgb.at(x, y, c)) : rgb.at(x, y, c);
  const double mean = (sum[0] + sum[1] + sum[2]) / 3;
  ASSERT_GT(mean, 0) << developed;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(sum[c] / mean, 1.0, tolerance) << developed.filename() << " channel " << c;
}

// A flat grey card's raw file developed by dcraw with the camera's white
// balance into linear sRGB (`dcraw -w -o 1 -4 -T`), neutral within `tolerance`.
void expectDevelopsNeutral(const std::filesystem::path& dng, double tolerance) {
  const RunResult d = runProgram("dcraw", {"-w", "-o", "1", "-4", "-T", dng.string()});
  ASSERT_EQ(d.status, 0) << d.err;
  expectNeutral(std::filesystem::path(dng).replace_extension(".tiff"), tolerance);
}

TEST(RawDng, AGreyCardDevelopsNeutral) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  const RunResult r = runLensrt({"render", (dir / "sky.gltf").string(), "--env", "constant:0.18", "--film",
                                 "radiance", "--res", "32x24", "--spp", "4", "-q", "-o",
                                 (dir / "a.exr").string(), "--raw", (dir / "a.dng").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expectDevelopsNeutral(dir / "a.dng", 0.02);
}

// A camera's measured curves, read here from the data file (rows of
// wavelength_nm,r,g,b at 10 nm) and interpolated linearly, 0 outside.
struct Curves {
  std::vector<std::array<double, 4>> rows;
  double at(double nm, int c) const {
    for (std::size_t i = 0; i + 1 < rows.size(); ++i)
      if (nm >= rows[i][0] && nm <= rows[i + 1][0]) {
        const double t = (nm - rows[i][0]) / (rows[i + 1][0] - rows[i][0]);
        return rows[i][std::size_t(c) + 1] * (1 - t) + rows[i + 1][std::size_t(c) + 1] * t;
      }
    return 0.0;
  }
};
Curves readCurves(const std::string& camera) {
  std::ifstream in(std::string(LENSRT_SOURCE_DIR) + "/data/sensor-responses/" + camera + ".csv");
  Curves curves;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'w') continue;
    std::array<double, 4> row{};
    char comma = 0;
    std::istringstream fields(line);
    fields >> row[0] >> comma >> row[1] >> comma >> row[2] >> comma >> row[3];
    curves.rows.push_back(row);
  }
  EXPECT_GT(curves.rows.size(), 30u) << camera;
  return curves;
}

// Each channel's mean over the sites of that colour of dcraw's undeveloped
// mosaic (`dcraw -D -4 -T`, RGGB).
std::array<double, 3> siteMeans(const std::filesystem::path& dng) {
  const RunResult d = runProgram("dcraw", {"-D", "-4", "-T", dng.string()});
  EXPECT_EQ(d.status, 0) << d.err;
  const Tiff raw = readTiff(std::filesystem::path(dng).replace_extension(".tiff"));
  std::array<double, 3> sum{}, count{};
  for (int y = 0; y < raw.height; ++y)
    for (int x = 0; x < raw.width; ++x) {
      const std::size_t colour = std::size_t("RGGB"[(y & 1) * 2 + (x & 1)] == 'R'   ? 0
                                             : "RGGB"[(y & 1) * 2 + (x & 1)] == 'G' ? 1
                                                                                    : 2);
      sum[colour] += raw.at(x, y);
      count[colour] += 1;
    }
  return {sum[0] / count[0], sum[1] / count[1], sum[2] / count[2]};
}

// The render's luminance (linear sRGB) before the readout, as the mean over the frame.
double renderLuminance(const std::filesystem::path& exr) {
  const Image img = readImage(exr);
  double y = 0;
  for (int py = 0; py < img.height; ++py)
    for (int px = 0; px < img.width; ++px)
      y += 0.2126 * img.at(px, py, img.channelIndex("noiseless.R")) +
           0.7152 * img.at(px, py, img.channelIndex("noiseless.G")) +
           0.0722 * img.at(px, py, img.channelIndex("noiseless.B"));
  y /= double(img.width) * img.height;
  EXPECT_GT(y, 0.01) << exr;
  return y;
}

struct PhysicalExposure {
  double iso, pitchM, quantumEfficiency, dnPerElectron, blackLevelDn;
};

// With a camera's response the sensor counts, in each channel, the
// photo-electrons its curve absorbs, the curves being the quantum efficiency
// (their peak is the sensor's QE). Computed from the physics of a flat field
// of D65 whose render has luminance `y`: the pixel's exposure H = y x 78 /
// ISO lux seconds, the light's spectral irradiance E(l) = H D65(l) / (683
// lm/W integral of ybar D65), its photons E(l) l / (h c), times the pitch
// squared and QE x curve(l) / peak. Each channel's mean over its sites of the
// mosaic, less the black level, is within 1% of that.
void expectCountsPhotons(const std::filesystem::path& dng, const std::string& camera, double y,
                         const PhysicalExposure& e) {
  const Curves curves = readCurves(camera);
  double peak = 0;
  for (const auto& row : curves.rows) peak = std::max({peak, row[1], row[2], row[3]});
  double ybarD65 = 0;
  for (double nm = 360; nm <= 830; nm += 1) ybarD65 += cieXyzMatching(nm).y * d65(nm);
  constexpr double h = 6.62607015e-34, c = 299792458.0;
  const double lux = y * 78.0 / e.iso;  // lux seconds
  const std::array<double, 3> measured = siteMeans(dng);
  for (int ch = 0; ch < 3; ++ch) {
    double photons = 0;  // per square metre, through the channel's curve
    for (double nm = 360; nm <= 830; nm += 1)
      photons += lux * d65(nm) / (683.0 * ybarD65) * (nm * 1e-9 / (h * c)) * curves.at(nm, ch) / peak;
    const double electrons = photons * e.pitchM * e.pitchM * e.quantumEfficiency;
    const double counted = (measured[std::size_t(ch)] - e.blackLevelDn) / e.dnPerElectron;
    EXPECT_NEAR(counted / electrons, 1.0, 0.01)
        << camera << " channel " << ch << ": " << counted << " electrons, expected " << electrons;
  }
}

// The photon counts (expectCountsPhotons) through an ADC that adds nothing
// but rounding. A 1% tolerance: photon noise over the ~300 sites of a colour is 0.1%, and
// all three agree within 0.1%; taking every channel's photons at 555 nm (no
// mean wavelength per channel) fails it, with red 8%, green 5% and blue 17% off.
TEST(RawDng, ACameraCountsThePhotonsItsCurvesAbsorb) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  // A noiseless ADC but for the photons: 0.05 DN/e over 16 bits and no clipping.
  cli::writeFile(dir / "counting.json",
                 R"({"name": "counting", "full_well_e": 1000000, "gain_dn_per_e": 0.05, "base_iso": 100,
                     "read_noise_e": 0, "dark_current_e_per_s": 0, "prnu_percent": 0, "dsnu_percent": 0,
                     "adc_bits": 16, "black_level_dn": 0, "quantum_efficiency": 0.6})");
  // At ISO 200 the analog gain doubles the base ISO's 0.05 DN/e.
  const double iso = 200, pitch = 4e-6, qe = 0.6, dnPerElectron = 0.05 * iso / 100;
  const RunResult r = runLensrt({"render",
                                 (dir / "sky.gltf").string(),
                                 "--env",
                                 "constant:1",
                                 "--res",
                                 "40x30",
                                 "--sensor",
                                 "0.16x0.12",
                                 "--spp",
                                 "64",
                                 "--film",
                                 "irradiance",
                                 "--exposure",
                                 "physical",
                                 "--iso",
                                 "200",
                                 "--shutter",
                                 "1/100",
                                 "--noise",
                                 "on",
                                 "--sensor-params",
                                 (dir / "counting.json").string(),
                                 "--sensor-response",
                                 "nikon-d850",
                                 "-q",
                                 "-o",
                                 (dir / "a.exr").string(),
                                 "--raw",
                                 (dir / "a.dng").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expectCountsPhotons(dir / "a.dng", "nikon-d850", renderLuminance(dir / "a.exr"),
                      {iso, pitch, qe, dnPerElectron, 0.0});
}

// A camera's raw file holds its own RGB, unbalanced: AsShotNeutral is the
// camera RGB of the white balance's light (D65 here), which dcraw turns into
// its multipliers (1 / neutral, green 1), computed here from the curves; and
// a grey card develops neutral through the response's own ColorMatrix1.
TEST(RawDng, ACameraRawDevelopsNeutralByItsOwnNeutral) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  const RunResult r =
      runLensrt({"render", (dir / "sky.gltf").string(), "--env", "constant:0.18", "--film", "radiance",
                 "--res", "32x24", "--spp", "64", "--sensor-response", "nikon-d850", "-q", "-o",
                 (dir / "a.exr").string(), "--raw", (dir / "a.dng").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const Curves curves = readCurves("nikon-d850");
  std::array<double, 3> neutral{};
  for (double nm = 360; nm <= 830; nm += 1)
    for (int ch = 0; ch < 3; ++ch) neutral[std::size_t(ch)] += curves.at(nm, ch) * d65(nm);
  const RunResult i = runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()});
  const std::size_t at = i.out.find("Camera multipliers: ");
  ASSERT_NE(at, std::string::npos) << i.out;
  std::istringstream multipliers(i.out.substr(at + 20));
  std::array<double, 3> m{};
  multipliers >> m[0] >> m[1] >> m[2];
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(m[std::size_t(ch)] / m[1], neutral[1] / neutral[std::size_t(ch)], 0.005 * m[std::size_t(ch)])
        << "channel " << ch << "\n"
        << i.out;
  expectDevelopsNeutral(dir / "a.dng", 0.01);
}

bool haveDarktable() {
  return runProgram("sh", {"-c", "command -v darktable-cli"}).status == 0;
}

// darktable-cli develops `dngs` in one start into 16-bit linear sRGB TIFFs
// dt_NAME.tif in `dir`: the as-shot white balance, the file's ColorMatrix1
// (an unknown camera's), and no scene-referred workflow (whose exposure and
// filmic curve keep a grey grey, but not linear). Its configuration and cache
// stay in `dir`, not in HOME. Its start is most of its time: 2-2.5 s on the
// 2-core CI machine for the three files, about 1.5 s of it per extra start.
void developWithDarktable(const TempDir& dir, const std::vector<std::filesystem::path>& dngs) {
  std::vector<std::string> args = {"XDG_CONFIG_HOME=" + (dir / "xdg").string(),
                                   "XDG_CACHE_HOME=" + (dir / "xdg").string(), "darktable-cli"};
  for (const auto& dng : dngs) args.insert(args.end(), {"--import", dng.string()});
  args.insert(args.end(),
              {(dir / "dt_$(FILE_NAME)").string(), "--out-ext", "tif", "--icc-type", "LIN_REC709", "--core",
               "--configdir", (dir / "darktable").string(), "--cachedir", (dir / "darktable").string(),
               "--disable-opencl", "--conf", "plugins/imageio/format/tiff/bpp=16", "--conf",
               "plugins/imageio/format/tiff/compress=0", "--conf", "plugins/darkroom/workflow=none"});
  const RunResult d = runProgram("env", args);
  ASSERT_EQ(d.status, 0) << d.out << d.err;
}

bool haveRawTherapee() {
  return runProgram("sh", {"-c", "command -v rawtherapee-cli"}).status == 0;
}

// rawtherapee-cli (5.9) develops `dngs` into 16-bit TIFFs rt/NAME.tif in
// `dir`: RawTherapee's neutral processing (no curves, no exposure change)
// with the camera's white balance (AsShotNeutral), the file's ColorMatrix1
// ("(camera)", not a bundled DCP of the body's name) and sRGB output, whose
// curve expectNeutral undoes. It takes files over 256 pixels wide only
// ("Error loading file" below). Its options stay in `dir`.
void developWithRawTherapee(const TempDir& dir, const std::vector<std::filesystem::path>& dngs) {
  cli::writeFile(dir / "neutral.pp3",
                 "[White Balance]\nEnabled=true\nSetting=Camera\n\n"
                 "[Color Management]\nInputProfile=(camera)\nToneCurve=false\n"
                 "ApplyLookTable=false\nApplyHueSatMap=false\n"
                 "WorkingProfile=sRGB\nOutputProfile=RTv4_sRGB\n");
  std::filesystem::create_directories(dir / "rt");
  std::vector<std::string> args = {"XDG_CONFIG_HOME=" + (dir / "xdg").string(),
                                   "XDG_CACHE_HOME=" + (dir / "xdg").string(),
                                   "HOME=" + dir.path().string(),
                                   "rawtherapee-cli",
                                   "-q",
                                   "-o",
                                   (dir / "rt").string(),
                                   "-p",
                                   (dir / "neutral.pp3").string(),
                                   "-t",
                                   "-b16",
                                   "-Y",
                                   "-c"};
  for (const auto& dng : dngs) args.push_back(dng.string());
  const RunResult d = runProgram("env", args);
  ASSERT_EQ(d.status, 0) << d.out << d.err;
  ASSERT_EQ(d.out.find("Error"), std::string::npos) << d.out << d.err;
}

// A photon-counted raw file's colour. A camera's channels take different
// shares of the light's photons (the D850's red 1.14 and blue 0.89 of
// green's, per camera value), so the mosaic of a readout with physical
// exposure holds camera RGB scaled by them, and its AsShotNeutral and
// ColorMatrix1 must describe it so scaled. For three bodies, one render each
// of the flat wall (a grey card under D65 filling the frame; noise on,
// physical exposure, the default sensor with its black level, read noise and
// fixed patterns) checks both together: the mosaic's photon counts against
// the physics within 1% (expectCountsPhotons), and the card developed neutral
// within 2% in linear RGB by dcraw, darktable and RawTherapee (each skipped
// when not installed). The metadata of unscaled camera RGB (before issue 39's
// fix) develops the cards at R/mean 1.18-1.20 and B/mean 0.81-0.82 in every
// body and developer (R and B fail in all eight developments); a readout that leaves out the
// channels' electron shares fails the photon counts by 2-38%.
//
// RawTherapee develops the EOS 5D Mark IV's card at R/mean 1.59, G 0.48, B
// 0.93, whatever the colour tags: its camconst.json gives that body (found by
// the file's Make and Model) the real sensor's masked areas, rows 54-4534 and
// columns 4-132, where it measures the black level; in lensrt's mosaic those
// are lit sites. The same file with Model "EOS 5D Mark XX" develops neutral
// within 0.6%. So RawTherapee checks the two bodies it knows no sensor
// geometry of.
TEST(RawDng, PhotonCountedCamerasDevelopNeutral) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  // The default sensor: 0.2 DN/e at ISO 100, black level 64 DN, QE 0.5, a
  // full well of 20000 e; 4 um pixels take 3300-3900 e of green here.
  const PhysicalExposure exposure{100, 4e-6, 0.5, 0.2, 64};
  const std::vector<std::string> bodies = {"nikon-d850", "canon-eos-5d-mark-iv", "sony-ilce-7m3"};
  std::vector<std::filesystem::path> dngs, rawTherapeeDngs;
  for (const std::string& body : bodies) {
    dngs.push_back(dir / (body + ".dng"));
    if (body != "canon-eos-5d-mark-iv") rawTherapeeDngs.push_back(dngs.back());
    // 320 x 240 sites of 4 um: RawTherapee takes files over 256 wide only.
    // 4 spp: a pixel's colour noise from the few wavelengths it sampled
    // shifts darktable's and RawTherapee's means (most likely their clipping
    // out of gamut, not looked into): at 1 spp they develop these cards up
    // to 2.9% and 4.6% off (red high, green low), at 4 spp within 1.2%;
    // dcraw within 0.6% at either.
    const RunResult r = runLensrt({"render",
                                   std::string(LENSRT_SOURCE_DIR) + "/scenes/flat_wall.gltf",
                                   "--res",
                                   "320x240",
                                   "--sensor",
                                   "1.28x0.96",
                                   "--spp",
                                   "4",
                                   "--film",
                                   "irradiance",
                                   "--exposure",
                                   "physical",
                                   "--iso",
                                   "100",
                                   "--shutter",
                                   "1/500",
                                   "--noise",
                                   "on",
                                   "--sensor-response",
                                   body,
                                   "-q",
                                   "-o",
                                   (dir / (body + ".exr")).string(),
                                   "--raw",
                                   dngs.back().string()});
    ASSERT_EQ(r.status, 0) << r.err;
    expectCountsPhotons(dngs.back(), body, renderLuminance(dir / (body + ".exr")), exposure);
    expectDevelopsNeutral(dngs.back(), 0.02);
  }
  if (haveDarktable()) {
    developWithDarktable(dir, dngs);
    for (const std::string& body : bodies) expectNeutral(dir / ("dt_" + body + ".tif"), 0.02);
  } else {
    std::cout << "darktable-cli not installed: not checked (tools/setup installs it)\n";
  }
  if (haveRawTherapee()) {
    developWithRawTherapee(dir, rawTherapeeDngs);
    for (const auto& dng : rawTherapeeDngs)
      expectNeutral(dir / "rt" / dng.filename().replace_extension(".tif"), 0.02, true);
  } else {
    std::cout << "rawtherapee-cli not installed: not checked (tools/setup installs it)\n";
  }
}

}  // namespace
}  // namespace lensrt
