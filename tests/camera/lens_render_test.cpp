// The full lens (dgauss-50mm, the lecture's double Gauss) in renders: a sharp
// edge at the focus distance, the predicted blur of one at twice it, and the
// relative illumination under a uniform sky against `lensrt lens plot`.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "camera/film_mapping.h"
#include "camera/lens_camera.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"
#include "render/environment.h"
#include "render_test_util.h"

namespace lensrt {
namespace {

LensCamera dgauss50(const FilmGeometry& film, double fNumber, double focusM) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = fNumber;
  p.focusMetres = focusM;
  return LensCamera(Transform(), film, loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-50mm.dat"),
                    p, Exposure{}, warnings);
}

// Row-averaged profile of an emissive half-plane x >= 0 at `distanceM`
// (wider than the field by far), normalised to 0 on the dark side and 1 on
// the bright one (the means of the outer 6 columns).
std::vector<double> edgeProfile(const Camera& cam, double distanceM, int spp) {
  const float d = float(distanceM);
  std::vector<double> p = test::columnProfile(
      test::renderScene(test::rectangleScene(0.0f, d, -d, d, d, 1.0f), cam, Environment(), spp));
  const std::size_t n = p.size(), k = 6;
  double dark = 0, bright = 0;
  for (std::size_t i = 0; i < k; ++i) {
    dark += p[i] / k;
    bright += p[n - 1 - i] / k;
  }
  for (double& v : p) v = (v - dark) / (bright - dark);
  return p;
}

// The pixel profile of an edge at the film centre blurred by a uniform disk
// of diameter `diskPx`: the disk's edge spread function (the circular
// segment's area) averaged over each box pixel.
std::vector<double> diskEdgeProfile(int width, double diskPx) {
  std::vector<double> p(width);
  const double radius = diskPx / 2, edge = width / 2.0;
  const int steps = 400;
  for (int i = 0; i < width; ++i) {
    double sum = 0;
    for (int j = 0; j < steps; ++j) sum += test::diskEdgeSpread((i + (j + 0.5) / steps - edge) / radius);
    p[i] = sum / steps;
  }
  return p;
}

// 12 um pixels on a 0.77 x 0.096 mm crop of the film's centre: the edge
// images on the axis, where the rows see the same profile.
constexpr double kPixelMm = 0.012;
const FilmGeometry kEdgeFilm{64, 8, 64 * kPixelMm, 8 * kPixelMm};

// At f/8 focused at 1.5 m, an edge at 1.5 m is sharp: its 10-90% rise is
// at most 1.5 pixels (a perfect edge gives 0.8: the box pixel alone).
TEST(LensRender, EdgeAtTheFocusDistanceIsSharpAtF8) {
  const LensCamera cam = dgauss50(kEdgeFilm, 8, 1.5);
  const std::vector<double> profile = edgeProfile(cam, 1.5, 64);
  const double width = test::riseWidth(profile);
  RecordProperty("rise_10_90_px", std::to_string(width));
  std::printf("10-90%% rise of the focused edge: %.3f px\n", width);
  EXPECT_LE(width, 1.5) << "10-90% rise in pixels";
  EXPECT_GE(width, 0.7) << "the box pixel alone spreads a perfect edge over 0.8 pixels";
}

// The same focus, the edge at 3 m: the blur is the cone from the edge's
// paraxial image through the exit pupil, a uniform disk of diameter
// b = D_xp |film - z'| / (z' - z_xp) on the film. The 10-90% rise equals
// that of the disk's edge spread function (box-filtered by the pixels, as
// the render is) within 6%: measured 2.4% wider at 512 spp (the residual
// spherical aberration at f/8 makes the real blur a little less uniform than
// the paraxial disk), plus about 1% of noise at 128 spp.
TEST(LensRender, EdgeAtTwiceTheFocusDistanceBlursByTheExitPupilCone) {
  const double focusM = 1.5;
  const LensCamera cam = dgauss50(kEdgeFilm, 8, focusM);
  const ParaxialData& p = cam.lens().paraxial();
  const Conjugate c2 = paraxialConjugate(p, 2 * focusM * 1e3);
  const double diskPx =
      p.exitPupilDiameter * std::abs(cam.filmZ() - c2.imageZ) / (c2.imageZ - p.exitPupilZ) / kPixelMm;
  const double predicted = test::riseWidth(diskEdgeProfile(kEdgeFilm.width, diskPx));
  const double width = test::riseWidth(edgeProfile(cam, 2 * focusM, 128));
  RecordProperty("blur_disk_px", std::to_string(diskPx));
  RecordProperty("rise_10_90_px", std::to_string(width));
  RecordProperty("predicted_rise_px", std::to_string(predicted));
  std::printf("blur disk %.3f px: 10-90%% rise %.3f px, predicted %.3f px\n", diskPx, width, predicted);
  EXPECT_NEAR(width, predicted, 0.06 * predicted) << "10-90% rise in pixels";
  EXPECT_GT(width, 2 * 1.5) << "clearly wider than the sharp edge's limit";
}

// `lensrt lens plot --what relative-illumination --csv`: film radius (mm) and
// E(r)/E(0) per row; empty when the run fails.
std::vector<std::pair<double, double>> plottedRelativeIllumination(const std::vector<std::string>& args) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lensrt_ri_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string csv = (dir / "ri.csv").string(), log = (dir / "log.txt").string();
  std::vector<std::string> all{"lens",  "plot", "dgauss-50mm", "--what", "relative-illumination",
                               "--csv", csv};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<std::pair<double, double>> curve;
  if (test::runLensrt(all, log) == 0) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("film_radius_mm,relative_illumination,", 0), 0u) << line;
    while (std::getline(in, line)) {
      std::istringstream row(line);
      double r = 0, ri = 0;
      char comma = 0;
      if (row >> r >> comma >> ri) curve.emplace_back(r, ri);
    }
  } else {
    std::ifstream in(log);
    ADD_FAILURE() << "lensrt lens plot failed: " << std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::filesystem::remove_all(dir);
  return curve;
}

double interpolate(const std::vector<std::pair<double, double>>& curve, double r) {
  const auto hi = std::lower_bound(curve.begin(), curve.end(), std::pair{r, -1.0});
  if (hi == curve.begin()) return hi->second;
  if (hi == curve.end()) return curve.back().second;
  const auto lo = hi - 1;
  return lo->second + (r - lo->first) / (hi->first - lo->first) * (hi->second - lo->second);
}

// Under a uniform sky of radiance 1, the render through dgauss-50mm (f/2.8,
// focused at 2 m, 36 x 24 mm) records E(r) / E(0) = the relative
// illumination the lens plot computes from exact rays (cos^4, vignetting,
// pupil aberration): at f/2.8 vignetting sets in near 12 mm and the corner
// gets 34% of the centre. The render's pixels are averaged in 1 mm rings, normalised
// by the centre (r < 3 mm), and compared with the plot's curve
// interpolated at the same pixel centres. Tolerance: 4 sigma of the render's
// noise (the variance AOV, propagated through the ring and the centre means)
// plus 0.4% for the plot's deterministic midpoint-rule integration, whose
// grid wobbles the curve by about 0.15% (it reads 1.0014 at 0.5 mm).
TEST(LensRender, RelativeIlluminationUnderAUniformSkyMatchesTheLensPlot) {
  const double fNumber = 2.8, focusM = 2.0;
  const auto curve = plottedRelativeIllumination(
      {"--fstop", std::to_string(fNumber), "--focus", std::to_string(focusM), "--sensor", "36x24"});
  ASSERT_GE(curve.size(), 20u);
  const FilmGeometry film{96, 64, 36.0, 24.0};  // 0.375 mm pixels
  const LensCamera cam = dgauss50(film, fNumber, focusM);
  // Nothing to see but the sky: the square sits behind the camera.
  const test::RenderedImage img = test::renderScene(test::squareScene(-5.0f, 0.1f, 0.0f), cam,
                                                    Environment::constant({1, 1, 1}), 64, true);
  const double ring = 1.0, centre = 3.0;
  const int rings = int(std::ceil(sensorHalfDiagonalMm(film) / ring));
  std::vector<double> value(rings, 0), variance(rings, 0), plotted(rings, 0), count(rings, 0);
  double cValue = 0, cVariance = 0, cPlotted = 0, cCount = 0;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      const Vec2d mm = uprightSensorPointMm(film, {x + 0.5f, y + 0.5f});
      const double r = std::hypot(mm.x, mm.y);
      const double v = img.image.at(x, y, img.red), var = img.image.at(x, y, img.varianceR);
      const double ri = interpolate(curve, r);
      const int k = std::min(rings - 1, int(r / ring));
      value[k] += v;
      variance[k] += var;
      plotted[k] += ri;
      count[k] += 1;
      if (r < centre) {
        cValue += v;
        cVariance += var;
        cPlotted += ri;
        cCount += 1;
      }
    }
  // The centre's scale: render value per unit relative illumination.
  const double scale = (cValue / cCount) / (cPlotted / cCount);
  const double scaleRelSigma = std::sqrt(cVariance) / cValue;
  double worst = 0;
  for (int k = 0; k < rings; ++k) {
    if (count[k] == 0) continue;
    const double measured = value[k] / count[k] / scale, expected = plotted[k] / count[k];
    const double sigma = measured * std::hypot(std::sqrt(variance[k]) / value[k], scaleRelSigma);
    worst = std::max(worst, std::abs(measured - expected) / sigma);
    std::printf("ring %4.1f-%4.1f mm: render %.4f +- %.4f, plot %.4f\n", k * ring, (k + 1) * ring, measured,
                sigma, expected);
    EXPECT_NEAR(measured, expected, 4 * sigma + 0.004)
        << "relative illumination, ring from " << k * ring << " mm";
  }
  RecordProperty("worst_deviation_sigma", std::to_string(worst));
}

}  // namespace
}  // namespace lensrt
