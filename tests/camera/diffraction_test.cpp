// --diffraction on against the closed forms of Fraunhofer diffraction by a
// round pupil. For each model (thin, thick, full lens) the same samples are
// traced with and without diffraction: the change of the ray's direction
// cosines is the far-field bend alone, whatever the lens's aberrations, and
// for a round entrance pupil of radius a = f / (2N) its density is the Airy
// pattern, whose encircled energy is 1 - J0(v)^2 - J1(v)^2 at
// v = 2 pi a sin(theta) / lambda (83.8% inside the first dark ring, v =
// 3.8317: radius 1.22 lambda N on the film). A bend scaled by the pupil's
// diameter instead of its radius moves these figures by far more than the
// tolerance (injected: the encircled energies then miss by 0.05 to 0.4). A
// 6-blade stop's bends concentrate along 6 directions, a 7-blade stop's along
// 14, each on an edge's normal (injected: a round table finds no spike, a
// table turned by 15 degrees puts all 20 off the normals).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "core/warnings.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

constexpr double kFNumber = 16.0;
constexpr int kSamples = 20000;

// The bends (in direction cosines) of `samples` rays from the film's centre
// at `wavelengthNm`, with `on` diffracting and `off` the same camera without.
std::vector<Vec2d> bends(const Camera& on, const Camera& off, float wavelengthNm, int samples = kSamples) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const FilmGeometry& film = on.film();
  std::vector<Vec2d> out;
  while (int(out.size()) < samples) {
    CameraSample s;
    s.film = {0.5f * float(film.width), 0.5f * float(film.height)};
    s.lens = {u(random), u(random)};
    s.diffraction = {u(random), u(random)};
    s.wavelengthNm = wavelengthNm;
    const std::optional<CameraRay> a = on.generateRay(s), b = off.generateRay(s);
    if (!a || !b) continue;
    out.push_back({double(a->ray.direction.x) - double(b->ray.direction.x),
                   double(a->ray.direction.y) - double(b->ray.direction.y)});
  }
  return out;
}

// Encircled energy of the Airy pattern within v.
double airyEncircled(double v) {
  const double j0 = std::cyl_bessel_j(0.0, v), j1 = std::cyl_bessel_j(1.0, v);
  return 1.0 - j0 * j0 - j1 * j1;
}

// The bends' encircled energy against the Airy pattern's at several radii,
// for a round pupil of radius a (mm) at `wavelengthNm`.
void expectAiry(const std::vector<Vec2d>& bent, double pupilRadiusMm, double wavelengthNm) {
  const double toV = 2.0 * kPi * pupilRadiusMm / (wavelengthNm * 1e-6);
  for (const double v : {1.0, 2.0, 3.8317, 7.0156}) {
    int inside = 0;
    for (const Vec2d& b : bent) inside += std::hypot(b.x, b.y) * toV <= v;
    const double measured = double(inside) / double(bent.size());
    // 20000 samples: a standard error of at most 0.0035; the table's cells
    // (1/16 of a cycle per radius) and its edge (0.6% of the light beyond
    // 16 cycles, spread inside) add about as much.
    EXPECT_NEAR(measured, airyEncircled(v), 0.012) << "v " << v << " at " << wavelengthNm << " nm";
  }
}

TEST(Diffraction, AThinLensBendsRaysIntoTheAiryPatternOfItsAperture) {
  ThinLensParams p;
  p.focalLengthMm = 50.0;
  p.fNumber = kFNumber;
  p.focusMetres = kInfinity;
  const ThinLensCamera off(Transform(), test::testFilm(), p);
  p.diffraction = true;
  const ThinLensCamera on(Transform(), test::testFilm(), p);
  for (const float nm : {450.0f, 550.0f, 650.0f}) expectAiry(bends(on, off, nm), 50.0 / (2.0 * kFNumber), nm);
}

TEST(Diffraction, AThickLensBendsRaysIntoTheAiryPatternOfItsEntrancePupil) {
  const ParaxialData paraxial = computeParaxial(test::lectureDoubleGauss(0.5));
  ThickLensParams p = thickLensFromParaxial(paraxial, kFNumber, 3.0);
  const ThickLensCamera off(Transform(), test::testFilm(), p);
  p.diffraction = true;
  const ThickLensCamera on(Transform(), test::testFilm(), p);
  expectAiry(bends(on, off, 550.0f), paraxial.efl / (2.0 * kFNumber), 550.0);
}

TEST(Diffraction, TheFullLensBendsRaysIntoTheAiryPatternOfItsEntrancePupil) {
  const LensPrescription lens = test::lectureDoubleGauss(0.5);
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = kFNumber;
  p.focusMetres = kInfinity;
  const LensCamera off(Transform(), test::testFilm(), lens, p, Exposure{}, warnings);
  p.diffraction = true;
  const LensCamera on(Transform(), test::testFilm(), lens, p, Exposure{}, warnings);
  // At infinity focus the f-number is the focal length over the entrance
  // pupil's diameter.
  expectAiry(bends(on, off, 550.0f), computeParaxial(lens).efl / (2.0 * kFNumber), 550.0);
}

// The number of directions where the bends far from the centre (beyond 3
// cycles per radius, where the edges' diffraction dominates) gather: in
// 2-degree bins summed over 3 neighbours, those that hold more than twice
// the median and the most within +-8 degrees (the first of equals).
std::vector<double> spikes(const std::vector<Vec2d>& bent, double pupilRadiusMm, double wavelengthNm) {
  const double toCycles = pupilRadiusMm / (wavelengthNm * 1e-6);
  std::vector<double> bins(180, 0.0);
  for (const Vec2d& b : bent)
    if (std::hypot(b.x, b.y) * toCycles > 3.0) {
      const double degrees = std::atan2(b.y, b.x) * 180.0 / kPi + 360.0;
      bins[std::size_t(degrees / 2.0) % 180] += 1.0;
    }
  const auto at = [](const std::vector<double>& v, int i) { return v[std::size_t((i + 180) % 180)]; };
  std::vector<double> smooth(180);
  for (int i = 0; i < 180; ++i) smooth[std::size_t(i)] = at(bins, i - 1) + at(bins, i) + at(bins, i + 1);
  std::vector<double> sorted = smooth;
  std::nth_element(sorted.begin(), sorted.begin() + 90, sorted.end());
  std::vector<double> peaks;  // degrees, the bins' centres
  for (int i = 0; i < 180; ++i) {
    const double v = smooth[std::size_t(i)];
    bool peak = v > 2.0 * sorted[90];
    for (int k = 1; k <= 4 && peak; ++k) peak = v >= at(smooth, i - k) && v > at(smooth, i + k);
    if (peak) peaks.push_back(2.0 * i + 1.0);
  }
  return peaks;
}

// Along the edges' normals, at the blade rotation given (10 degrees: the
// first corner's angle; the normals lie half a blade's angle past each).
TEST(Diffraction, BladesMakeASpikePerBladeEdge) {
  for (const auto& [blades, expected] : {std::pair{6, 6}, std::pair{7, 14}}) {
    ThinLensParams p;
    p.focalLengthMm = 50.0;
    p.fNumber = kFNumber;
    p.focusMetres = kInfinity;
    p.aperture.blades = blades;
    p.aperture.rotationDegrees = 10.0;
    const ThinLensCamera off(Transform(), test::testFilm(), p);
    p.diffraction = true;
    const ThinLensCamera on(Transform(), test::testFilm(), p);
    // The bends are in units of the circumradius of the blades' polygon.
    const std::vector<double> found =
        spikes(bends(on, off, 550.0f, 200000), on.aperture().circumradius(), 550.0);
    ASSERT_EQ(int(found.size()), expected) << blades << " blades";
    const double period = 360.0 / expected;
    for (const double angle : found) {
      const double phase = std::fmod(angle - 10.0 - 180.0 / blades + 720.0, period);
      EXPECT_LT(std::min(phase, period - phase), 3.0)
          << blades << " blades, a spike at " << angle << " degrees";
    }
  }
}

// Diffraction moves light and never takes any: each ray keeps its weight,
// and with it off the rays are the geometric ones, bit for bit.
TEST(Diffraction, BendingKeepsTheWeightAndOffKeepsTheRays) {
  ThinLensParams p;
  p.fNumber = 8.0;
  p.focusMetres = 2.0;
  const ThinLensCamera off(Transform(), test::testFilm(), p);
  p.diffraction = true;
  const ThinLensCamera on(Transform(), test::testFilm(), p);
  EXPECT_FALSE(off.diffracts());
  EXPECT_TRUE(on.diffracts());
  CameraSample s;
  s.film = {10.3f, 7.9f};
  s.lens = {0.3f, 0.8f};
  s.diffraction = {0.9f, 0.2f};
  const std::optional<CameraRay> a = on.generateRay(s), b = off.generateRay(s);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->weight, b->weight);
  EXPECT_EQ(a->ray.origin.x, b->ray.origin.x);
  EXPECT_EQ(a->ray.origin.y, b->ray.origin.y);
  EXPECT_EQ(a->ray.origin.z, b->ray.origin.z);
  EXPECT_NE(a->ray.direction.x, b->ray.direction.x);
  EXPECT_NE(on.describe().find("diffraction=on"), std::string::npos);
  EXPECT_EQ(off.describe().find("diffraction"), std::string::npos);
}

}  // namespace
}  // namespace lensrt
