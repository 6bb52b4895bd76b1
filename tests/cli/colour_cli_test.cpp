// The film's colour end to end: --white-balance keeps a grey card grey under
// a coloured light (auto, or the light's colour temperature), --output-space
// gives the same render in another RGB (the images are the matrices' images
// of each other: the same paths, the same wavelengths), the EXR's
// chromaticities say which, and bad colour options are one-line errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "color/chromatic_adaptation.h"
#include "color/color_space.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

// A grey Lambertian card filling the view, 2 m below the camera, lit by the sky.
std::filesystem::path greyCard(const TempDir& dir) {
  cli::QuadScene scene;
  scene.quads = {{{{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}}, 0}};
  scene.materials = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":0},)"
                    R"("extensions":{"KHR_materials_specular":{"specularFactor":0}}})";
  const auto file = dir / "card.gltf";
  cli::writeFile(file, cli::quadsGltf(scene));
  return file;
}

Vec3d meanRgb(const Image& img) {
  Vec3d sum{0, 0, 0};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      sum += Vec3d{img.at(x, y, img.channelIndex("R")), img.at(x, y, img.channelIndex("G")),
                   img.at(x, y, img.channelIndex("B"))};
  return sum / double(img.width * img.height);
}

Vec3d renderCard(const TempDir& dir, const std::vector<std::string>& extra, ImageMetadata* meta = nullptr) {
  std::vector<std::string> args{"render", greyCard(dir).string(),     "--res", "24x24", "--spp", "16", "-q",
                                "-o",     (dir / "card.exr").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return meanRgb(readImage(dir / "card.exr", meta));
}

TEST(ColourCli, WhiteBalanceKeepsAGreyCardGrey) {
  const TempDir dir;
  // Under a warm sky the card is orange without a white balance.
  const Vec3d warm = renderCard(dir, {"--env", "constant:1,0.55,0.25"});
  EXPECT_GT(warm.x, 1.5 * warm.y);
  EXPECT_GT(warm.y, 1.5 * warm.z);
  // auto balances to the sky's colour: grey, within the colour noise.
  ImageMetadata meta;
  const Vec3d balanced = renderCard(dir, {"--env", "constant:1,0.55,0.25", "--white-balance", "auto"}, &meta);
  EXPECT_NEAR(balanced.x / balanced.y, 1.0, 0.01);
  EXPECT_NEAR(balanced.z / balanced.y, 1.0, 0.01);
  EXPECT_EQ(meta["lensrt:white_balance"].rfind("auto:x=", 0), 0u) << meta["lensrt:white_balance"];
  // Daylight at 6504 K is D65, the light of RGB (1, 1, 1): a white sky stays grey.
  const Vec3d daylight = renderCard(dir, {"--env", "constant:1", "--white-balance", "6504"}, &meta);
  EXPECT_NEAR(daylight.x / daylight.y, 1.0, 0.01);
  EXPECT_NEAR(daylight.z / daylight.y, 1.0, 0.01);
  EXPECT_EQ(meta["lensrt:white_balance"], "6504K");
  // Balanced for tungsten (3000 K), daylight looks blue.
  const Vec3d tungsten = renderCard(dir, {"--env", "constant:1", "--white-balance", "3000"});
  EXPECT_GT(tungsten.z, 1.3 * tungsten.x);
}

// A camera's response: its fitted matrix keeps a grey card grey, balanced to
// the sky automatically (a camera's default), and its own RGB is unbalanced.
TEST(ColourCli, ACameraResponseKeepsAGreyCardGrey) {
  const TempDir dir;
  for (const std::string camera : {"nikon-d850", "canon-eos-5d-mark-iv", "sony-ilce-7m3"}) {
    SCOPED_TRACE(camera);
    ImageMetadata meta;
    const Vec3d warm = renderCard(dir, {"--env", "constant:1,0.55,0.25", "--sensor-response", camera}, &meta);
    EXPECT_NEAR(warm.x / warm.y, 1.0, 0.01);
    EXPECT_NEAR(warm.z / warm.y, 1.0, 0.01);
    EXPECT_EQ(meta["lensrt:sensor_response"], camera);
    EXPECT_EQ(meta["lensrt:white_balance"].rfind("auto:x=", 0), 0u);
    const Vec3d daylight =
        renderCard(dir, {"--env", "constant:1", "--sensor-response", camera, "--white-balance", "none"});
    EXPECT_NEAR(daylight.x / daylight.y, 1.0, 0.01);
    EXPECT_NEAR(daylight.z / daylight.y, 1.0, 0.01);
    // The camera's own RGB: green leads under daylight, as in a raw file.
    const Vec3d raw = renderCard(
        dir, {"--env", "constant:1", "--sensor-response", camera, "--output-space", "camera"}, &meta);
    EXPECT_GT(raw.y, 1.2 * raw.x);
    EXPECT_GT(raw.y, 1.2 * raw.z);
    EXPECT_EQ(meta.count("chromaticities"), 0u);
  }
}

TEST(ColourCli, OutputSpacesAreTheSameRenderInAnotherRgb) {
  const TempDir dir;
  const std::string scene = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
  const auto render = [&](const std::string& space) {
    const auto out = dir / (space + ".exr");
    // One transport for all (auto would take RGB for sRGB and spectral for the others).
    const RunResult r = runLensrt({"render", scene, "--res", "24x24", "--spp", "4", "--seed", "5",
                                   "--spectral", "on", "--output-space", space, "-q", "-o", out.string()});
    EXPECT_EQ(r.status, 0) << r.err;
    ImageMetadata meta;
    Image img = readImage(out, &meta);
    EXPECT_EQ(meta["lensrt:output_space"], space);
    return std::pair{std::move(img), meta};
  };
  const auto [srgb, srgbMeta] = render("srgb");
  EXPECT_EQ(srgbMeta.at("chromaticities"), "0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329");
  const Mat3d fromSrgb = colorSpace(ColorSpaceId::Srgb).rgbToXyz;
  const Vec3d d65 = fromSrgb * Vec3d{1, 1, 1};
  for (const ColorSpaceId id : {ColorSpaceId::Rec2020, ColorSpaceId::AcesCg, ColorSpaceId::Xyz}) {
    const ColorSpace& space = colorSpace(id);
    const auto [img, meta] = render(std::string(space.name));
    // XYZ without a white balance is left alone; the RGB spaces adapt D65 to their white.
    const Mat3d adapt =
        id == ColorSpaceId::Xyz ? Mat3d{} : bradfordAdaptation(d65, space.rgbToXyz * Vec3d{1, 1, 1});
    const Mat3d m = space.xyzToRgb * adapt * fromSrgb;
    double worst = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const Vec3d a{srgb.at(x, y, 0), srgb.at(x, y, 1), srgb.at(x, y, 2)};
        const Vec3d want = m * a, got{img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)};
        for (int c = 0; c < 3; ++c)
          worst = std::max(
              worst, std::abs(got[c] - want[c]) / (1e-3 + std::abs(a.x) + std::abs(a.y) + std::abs(a.z)));
      }
    // Each space's film is scaled so that its white is exact: 1e-4 from the plain matrix.
    EXPECT_LT(worst, 2e-3) << space.name;
    EXPECT_NE(meta.at("chromaticities"), srgbMeta.at("chromaticities")) << space.name;
  }
}

TEST(ColourCli, BadColourOptionsAreOneLineErrors) {
  const TempDir dir;
  const std::string card = greyCard(dir).string(), out = (dir / "x.exr").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--white-balance", "900"},
       "--white-balance: expected auto, none or a colour temperature from 1500 to 25000 K"},
      {{"--white-balance", "warm"}, "got 'warm'"},
      {{"--output-space", "adobergb"}, "--output-space: expected srgb, rec2020, acescg, xyz or camera"},
      {{"--output-space", "camera"}, "the CIE 1931 observer has none"},
      {{"--spectral", "off", "--white-balance", "5000"}, "--white-balance: needs spectral transport"},
      {{"--spectral", "off", "--output-space", "xyz"}, "--output-space: needs spectral transport"},
  };
  for (const auto& [flags, message] : cases) {
    std::vector<std::string> args{"render", card, "--res", "8x8", "--spp", "1", "-o", out};
    args.insert(args.end(), flags.begin(), flags.end());
    const RunResult r = runLensrt(args);
    EXPECT_EQ(r.status, 2) << flags[0];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
  }
  // A preview's colours are sRGB.
  const RunResult png = runLensrt({"render", card, "--res", "8x8", "--spp", "1", "--output-space", "acescg",
                                   "-o", (dir / "x.png").string()});
  EXPECT_NE(png.status, 0);
  EXPECT_NE(png.err.find("--output-space: acescg needs an .exr output"), std::string::npos) << png.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace lensrt
