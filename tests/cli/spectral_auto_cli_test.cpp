// --spectral auto (issue 39): spectral where the image depends on
// wavelengths, RGB elsewhere; each rule of api/transport_choice.h read back
// from the EXR's lensrt:transport (and the transport the identity records).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kCornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";

// A glass slab (KHR_materials_dispersion, Abbe number 20) over a grey floor.
std::filesystem::path dispersiveScene(const TempDir& dir) {
  cli::QuadScene scene;
  scene.quads = {{{{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}}, 0},
                 {{{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}}, 1}};
  scene.materials =
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":0}},)"
      R"({"pbrMetallicRoughness":{"metallicFactor":0,"roughnessFactor":0},"extensions":{)"
      R"("KHR_materials_transmission":{"transmissionFactor":1},"KHR_materials_volume":{"thicknessFactor":0.1},)"
      R"("KHR_materials_dispersion":{"dispersion":1}}})";
  const auto file = dir / "glass.gltf";
  cli::writeFile(file, cli::quadsGltf(scene));
  return file;
}

struct Rendered {
  std::string transport;  // lensrt:transport
  std::string settings;   // lensrt:settings (its transport= is the film's)
  Image image;
};

Rendered render(const TempDir& dir, const std::string& scene, std::vector<std::string> extra) {
  const std::string out = (dir / "t.exr").string();
  std::vector<std::string> args{"render", scene, "--res", "8x6", "--spp", "1",
                                "--seed", "3",   "-q",    "-o",  out};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  Rendered x;
  x.image = readImage(out, &meta);
  x.transport = meta["lensrt:transport"];
  x.settings = meta["lensrt:settings"];
  return x;
}

bool filmIsSpectral(const Rendered& r) {
  return r.settings.find("transport=spectral") != std::string::npos;
}

TEST(SpectralAutoCli, EachRuleReadFromTheExr) {
  const TempDir dir;
  const std::vector<std::string> lens{"--camera", "lens", "--lens", "canon-rf50-51mm", "--fstop", "2.8"};
  const auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  struct Case {
    std::string scene;
    std::vector<std::string> args;
    std::string transport;
  };
  const std::vector<Case> cases{
      {kCornell, {}, "rgb (auto: nothing needs wavelengths)"},
      // cie1931 named is the default observer, not a camera.
      {kCornell, {"--sensor-response", "cie1931"}, "rgb (auto: nothing needs wavelengths)"},
      {kCornell, {"--sensor-response", "nikon-d850"}, "spectral (auto: a camera response)"},
      {kCornell, {"--white-balance", "3200"}, "spectral (auto: --white-balance or --output-space)"},
      {kCornell, {"--output-space", "acescg"}, "spectral (auto: --white-balance or --output-space)"},
      {dispersiveScene(dir).string(), {}, "spectral (auto: dispersive glass in the scene)"},
      {kCornell, lens, "spectral (auto: the lens disperses)"},
      // The thick lens's axial colour.
      {kCornell, {"--camera", "thick", "--lens", "canon-rf50-51mm"}, "spectral (auto: the lens disperses)"},
      // The same lens without its dispersion traced needs no wavelengths.
      {kCornell, with(lens, {"--dispersion", "off"}), "rgb (auto: nothing needs wavelengths)"},
      {kCornell, with(lens, {"--dispersion", "off", "--flare", "on", "--coatings", "single"}),
       "spectral (auto: coatings under flare)"},
      {kCornell, {"--camera", "thin", "--diffraction", "on"}, "spectral (auto: diffraction)"},
  };
  for (const Case& c : cases) {
    const Rendered r = render(dir, c.scene, with(c.args, {"--spectral", "auto"}));
    EXPECT_EQ(r.transport, c.transport) << testing::PrintToString(c.args);
    EXPECT_EQ(filmIsSpectral(r), c.transport.starts_with("spectral")) << r.settings;
  }
  // on and off say so, whatever the scene needs.
  EXPECT_EQ(render(dir, kCornell, with(lens, {"--spectral", "off"})).transport, "rgb (--spectral off)");
  EXPECT_EQ(render(dir, kCornell, {"--spectral", "on"}).transport, "spectral (--spectral on)");
  // auto is the default.
  EXPECT_EQ(render(dir, kCornell, {}).transport, "rgb (auto: nothing needs wavelengths)");
}

TEST(SpectralAutoCli, AutoIsTheResolvedTransportsImage) {
  const TempDir dir;
  // auto changes nothing but the choice: its pinhole image is --spectral off's bits.
  const Image autoImage = render(dir, kCornell, {"--spectral", "auto"}).image;
  const Image off = render(dir, kCornell, {"--spectral", "off"}).image;
  ASSERT_EQ(autoImage.pixels.size(), off.pixels.size());
  EXPECT_EQ(std::memcmp(autoImage.pixels.data(), off.pixels.data(), off.pixels.size() * sizeof(float)), 0);
  // A bad value is a one-line error naming the flag.
  const RunResult r =
      runLensrt({"render", kCornell, "--spectral", "maybe", "-q", "-o", (dir / "x.exr").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--spectral"), std::string::npos) << r.err;
  EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
}

}  // namespace
}  // namespace lensrt
