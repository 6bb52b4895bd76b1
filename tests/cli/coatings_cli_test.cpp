// --coatings end to end: a flat field seen through the full lens dims by the
// lens's axial transmittance at the centre, the EXR names the coating, and a
// render with another coating is not resumed or merged into this one.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

using cli::kSkyOnlyGltf;

std::vector<std::string> renderArgs(const TempDir& dir, const std::string& name,
                                    std::vector<std::string> extra, int spp = 16) {
  std::vector<std::string> a{"render",
                             (dir / "sky.gltf").string(),
                             "--env",
                             "constant:1",
                             "--res",
                             "24x16",
                             "--spp",
                             std::to_string(spp),
                             "--camera",
                             "lens",
                             "--lens",
                             "dgauss-100mm",
                             "--dispersion",
                             "off",
                             "--fstop",
                             "4",
                             "--seed",
                             "3",
                             "-q",
                             "-o",
                             (dir / name).string()};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

double centreG(const Image& img) {
  const int g = img.channelIndex("G");
  double sum = 0;
  for (int y = img.height / 2 - 1; y < img.height / 2 + 1; ++y)
    for (int x = img.width / 2 - 1; x < img.width / 2 + 1; ++x) sum += img.at(x, y, g);
  return sum / 4;
}

TEST(Coatings, FlatFieldDimsByTheAxialTransmittanceAndIsPartOfTheIdentity) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", kSkyOnlyGltf);
  RunResult r = runLensrt(renderArgs(dir, "lossless.exr", {}));
  ASSERT_EQ(r.status, 0) << r.err;
  r = runLensrt(renderArgs(dir, "none.exr", {"--coatings", "none", "--checkpoint", "1000"}));
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata lossMeta, noneMeta;
  const Image lossless = readImage(dir / "lossless.exr", &lossMeta),
              none = readImage(dir / "none.exr", &noneMeta);
  EXPECT_EQ(lossMeta["lensrt:coatings"], "off (lossless)");
  EXPECT_EQ(noneMeta["lensrt:coatings"], "none");

  // The same seed traces the same rays; only their weights differ, by the
  // Fresnel transmittance of rays close to the axis at f/4 (at the d line,
  // as lens info: dispersion off).
  r = runLensrt({"lens", "info", "dgauss-100mm", "--fstop", "4", "--coatings", "none", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const double axial = nlohmann::json::parse(r.out)["axial_transmittance"].get<double>();
  EXPECT_NEAR(axial, 0.59, 0.01);
  EXPECT_NEAR(centreG(none) / centreG(lossless), axial, 0.005 * axial);

  // Resuming the uncoated render without coatings is another render.
  r = runLensrt(renderArgs(dir, "out.exr", {"--resume", (dir / "none.exr").string()}, 32));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("the camera differs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("coatings=none"), std::string::npos) << r.err;
  EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace lensrt
