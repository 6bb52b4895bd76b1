// A surface closer than the lens focuses (ToyCar seen through dgauss-50mm
// with --focus auto): every model focuses at the lens's closest focus
// (magnification 1:1 for a lens file that states none), with one warning, and
// none degenerates: the four images are lit and framed alike.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

// Where the image's middle rows cross from the black quad (left) to the
// white wall (right): the column, with sub-pixel interpolation, at which the
// row mean passes halfway between its darkest and brightest column.
double edgeColumn(const Image& image) {
  const int r = image.channelIndex("R");
  std::vector<double> profile(image.width, 0.0);
  for (int y = image.height / 3; y < 2 * image.height / 3; ++y)
    for (int x = 0; x < image.width; ++x) profile[x] += image.at(x, y, r);
  double lo = profile[0], hi = profile[0];
  for (const double v : profile) lo = std::min(lo, v), hi = std::max(hi, v);
  const double half = 0.5 * (lo + hi);
  for (int x = 1; x < image.width; ++x)
    if (profile[x - 1] < half && profile[x] >= half)
      return x - 0.5 + (half - profile[x - 1]) / (profile[x] - profile[x - 1]);
  return -1;
}

TEST(CloseFocus, EveryModelFocusesAtTheLensClosestFocusAndFramesAlike) {
  const TempDir dir;
  // A white wall 6 cm in front of the entrance pupil, a black card just in
  // front of its left part up to 5 mm left of the axis (tan 0.083; the
  // half-width the lens sees at 1:1 is tan 0.18).
  constexpr float z = -0.06f, zCard = -0.0599f;
  cli::QuadScene scene;
  scene.quads = {
      {{{-0.5f, -0.5f, z}, {0.5f, -0.5f, z}, {0.5f, 0.5f, z}, {-0.5f, 0.5f, z}}, 0},
      {{{-0.5f, -0.5f, zCard}, {-0.005f, -0.5f, zCard}, {-0.005f, 0.5f, zCard}, {-0.5f, 0.5f, zCard}}, 1}};
  scene.materials = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0}},)"
                    R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0}})";
  scene.cameraPlacement = R"("translation":[0,0,0])";
  const auto gltf = dir / "close.gltf";
  cli::writeFile(gltf, cli::quadsGltf(scene));
  const auto out = dir / "compare";
  const RunResult r = runLensrt({"compare", gltf.string(), "--lens", "dgauss-50mm", "--fstop", "8", "--res",
                                 "64x36", "--spp", "16", "--seed", "2", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;

  // One warning for the four models, naming the lens and its closest focus.
  int warnings = 0;
  for (const std::string& line : cli::lines(r.err))
    if (line.find("--focus auto: the surface at") != std::string::npos) {
      ++warnings;
      EXPECT_NE(line.find("is closer than dgauss-50mm focuses; focusing at its closest, 0.09743 m"),
                std::string::npos)
          << line;
    }
  EXPECT_EQ(warnings, 1) << r.err;

  std::ifstream reportFile(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(reportFile);
  double pinholeEdge = -1;
  for (const char* model : {"pinhole", "thin", "thick", "lens"}) {
    SCOPED_TRACE(model);
    const nlohmann::json& m = report.at("models").at(model);
    if (std::string(model) != "pinhole") {
      EXPECT_NEAR(m.at("focus_m").get<double>(), 0.09743, 5e-5) << m;
    }
    const Image image = readImage(out / (std::string(model) + ".exr"));
    double mean = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) mean += image.at(x, y, image.channelIndex("R"));
    mean /= double(image.width) * image.height;
    EXPECT_GT(mean, 0.05) << "black image";
    const double edge = edgeColumn(image);
    EXPECT_GT(edge, 8);  // about 17.2 px from the left at 1:1
    EXPECT_LT(edge, 26);
    if (std::string(model) == "pinhole") {
      pinholeEdge = edge;
    } else {
      EXPECT_NEAR(edge, pinholeEdge, 2.0) << "framed unlike the pinhole";
    }
  }
}

}  // namespace
}  // namespace lensrt
