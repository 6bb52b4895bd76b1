// The lens's PSF and MTF by FFT of its pupil function, against closed forms.
//
// The aberration-free lens is a plano-convex singlet whose rear surface is a
// hyperboloid of conic constant -n^2: a collimated beam crossing the flat
// front face along the axis meets it and converges to one point exactly
// (a Cartesian surface), at every wavelength since the glass has no
// dispersion. Its measured RMS OPD is below 1e-6 waves. The stop sits in
// front of the flat face, so the entrance pupil is the stop.
#include "optics/psf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "core/constants.h"
#include "core/error.h"
#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/mtf.h"
#include "optics/spot_diagram.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

constexpr double kIndex = 1.5;
constexpr double kFocalMm = 50.0;

// f/N: a stop of diameter f / N in front of the plano-hyperbolic singlet.
LensSystem idealLens(double fNumber) {
  LensPrescription lens;
  lens.name = "plano-hyperbolic";
  Surface stop;
  stop.isStop = true;
  stop.apertureDiameter = kFocalMm / fNumber;
  stop.thickness = 1.0;
  Surface front;
  front.thickness = 5.0;
  front.apertureDiameter = 20.0;
  front.medium.nd = kIndex;
  Surface rear;
  rear.radius = -(kIndex - 1.0) * kFocalMm;
  rear.conic = -kIndex * kIndex;
  rear.apertureDiameter = 20.0;
  lens.surfaces = {stop, front, rear};
  return LensSystem(lens);
}

// The working f-number 1 / (2 sin theta) of the marginal ray: it leaves the
// hyperboloid at height h = f / 2N, sag z(h) = c h^2 / (1 + sqrt(1 - (1 + k)
// c^2 h^2)) (negative: toward the scene), toward the focus a focal length
// behind the vertex (a flat front face puts H' at the rear vertex). The
// hyperboloid does not keep Abbe's sine condition, so this is 0.15% (f/16)
// to 0.6% (f/8) above the paraxial N.
double workingFNumber(double fNumber) {
  const double h = kFocalMm / (2.0 * fNumber), c = 1.0 / (-(kIndex - 1.0) * kFocalMm), k = -kIndex * kIndex;
  const double sag = c * h * h / (1.0 + std::sqrt(1.0 - (1.0 + k) * c * c * h * h));
  const double sine = h / std::hypot(h, kFocalMm - sag);
  return 1.0 / (2.0 * sine);
}

PsfSettings mono(const LensSystem& lens, double wavelengthNm, int pupilSamples, int padding) {
  PsfSettings s;
  s.filmDistanceMm = focusFilmDistance(lens, kInfinity);
  s.wavelengthsNm = {wavelengthNm};
  s.weights = {1.0};
  s.pupilSamples = pupilSamples;
  s.padding = padding;
  return s;
}

// The first minimum of the PSF along +-x and +-y from its centre (mm),
// averaged over the four directions. Between samples the PSF along a line
// of samples is its trigonometric interpolant (the intensity is band-limited
// within the grid's frequencies), minimised by golden sections around the
// lowest sample.
double firstZeroMm(const Psf& psf) {
  const int m = psf.size, c = m / 2;
  double sum = 0.0;
  for (const bool alongX : {true, false}) {
    std::vector<double> line(std::size_t(m), 0.0);
    for (int k = 0; k < m; ++k) line[std::size_t(k)] = alongX ? psf.at(k, c) : psf.at(c, k);
    // Interpolant at fractional sample x: sum over frequencies of the DFT.
    std::vector<std::complex<double>> spectrum(static_cast<std::size_t>(m));
    for (int f = 0; f < m; ++f)
      for (int k = 0; k < m; ++k)
        spectrum[std::size_t(f)] += line[std::size_t(k)] * std::polar(1.0, -2.0 * kPi * f * k / m);
    const auto at = [&](double x) {
      double v = 0.0;
      for (int f = 0; f < m; ++f) {
        const int signedF = f <= m / 2 ? f : f - m;
        v += std::real(spectrum[std::size_t(f)] * std::polar(1.0, 2.0 * kPi * signedF * x / m));
      }
      return v / m;
    };
    for (const int dir : {1, -1}) {
      int k = 1;
      while (line[std::size_t(c + dir * (k + 1))] < line[std::size_t(c + dir * k)]) ++k;
      double a = c + dir * (k - 1), b = c + dir * (k + 1);
      for (int step = 0; step < 60; ++step) {
        const double x1 = b - 0.618034 * (b - a), x2 = a + 0.618034 * (b - a);
        (at(x1) < at(x2) ? b : a) = at(x1) < at(x2) ? x2 : x1;
      }
      sum += std::abs(0.5 * (a + b) - c) * psf.pixelMm;
    }
  }
  return sum / 4.0;
}

constexpr double kAiryZero = 1.2196698912665045;  // first zero of J1 / pi

// Focused at infinity, the d, F and C lines one at a time.
TEST(Psf, AberrationFreeAiryFirstZeroIs122LambdaN) {
  const LensSystem lens = idealLens(16.0);
  const double n = workingFNumber(16.0);
  for (const double wl : {kWavelengthFNm, kWavelengthDNm, kWavelengthCNm}) {
    const Psf psf = PsfModel(lens, mono(lens, wl, 65, 4)).psf();
    EXPECT_LT(psf.wavelengths[0].rmsWaves, 1e-6) << "the lens is not aberration-free";
    const double expected = kAiryZero * wl * 1e-6 * n;
    EXPECT_NEAR(firstZeroMm(psf) / expected, 1.0, 0.01) << wl << " nm";
    EXPECT_FALSE(psf.aliased());
  }
}

TEST(Psf, AberrationFreeEncircledEnergyAtTheFirstZeroIs838Percent) {
  const LensSystem lens = idealLens(16.0);
  const double wl = kWavelengthDNm;
  const Psf psf = PsfModel(lens, mono(lens, wl, 65, 4)).psf();
  const double v0 = kAiryZero * kPi;
  const double closedForm = 1.0 - std::pow(std::cyl_bessel_j(0.0, v0), 2);  // 0.8378
  // Measured 0.8371.
  EXPECT_NEAR(encircledEnergy(psf, kAiryZero * wl * 1e-6 * workingFNumber(16.0)), closedForm, 0.005);
}

// Every frequency the FFT gives, from 0 to the cutoff 1 / (lambda N), both
// directions, and the diffraction limit the MTF is plotted against.
TEST(Psf, AberrationFreeMtfIsTheDiffractionLimitedFormula) {
  const LensSystem lens = idealLens(8.0);
  const double wl = kWavelengthDNm;
  const Psf psf = PsfModel(lens, mono(lens, wl, 65, 4)).psf();
  const double cutoff = 1.0 / (wl * 1e-6 * workingFNumber(8.0));
  double worst = 0.0;
  int compared = 0;
  for (const bool limit : {false, true}) {
    const MtfSamples mtf = mtfSamples(psf, limit);
    for (std::size_t k = 0; k < mtf.tangential.size(); ++k) {
      const double f = double(k) * mtf.stepPerMm, expected = diffractionLimitedMtf(f, cutoff);
      worst = std::max({worst, std::abs(mtf.tangential[k] - expected), std::abs(mtf.sagittal[k] - expected)});
      compared += f < cutoff;
    }
  }
  EXPECT_GT(compared, 100);
  EXPECT_LT(worst, 0.005);  // measured 0.0024 over 118 frequencies
}

// Polychromatic: the MTF is the weighted mean of the wavelengths' OTFs
// (each PSF normalised to unit light), so here of their closed forms.
TEST(Psf, PolychromaticMtfIsTheWeightedMeanOfTheWavelengths) {
  const LensSystem lens = idealLens(8.0);
  PsfSettings s = mono(lens, kWavelengthFNm, 33, 4);
  s.wavelengthsNm = {kWavelengthFNm, kWavelengthCNm};
  s.weights = {3.0, 1.0};
  const Psf psf = PsfModel(lens, s).psf();
  const MtfCurves c = mtfCurves(psf, 200.0, 41);
  const double n = workingFNumber(8.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < c.frequencyPerMm.size(); ++k) {
    const double f = c.frequencyPerMm[k];
    const double expected = 0.75 * diffractionLimitedMtf(f, 1.0 / (kWavelengthFNm * 1e-6 * n)) +
                            0.25 * diffractionLimitedMtf(f, 1.0 / (kWavelengthCNm * 1e-6 * n));
    worst = std::max({worst, std::abs(c.tangential[k] - expected), std::abs(c.sagittal[k] - expected)});
  }
  EXPECT_LT(worst, 0.01);
}

// The RMS of the defocus OPD delta (1 - cos theta) over a pupil uniform in
// direction cosines s = sin theta up to na (piston removed), by quadrature.
double defocusRmsWaves(double delta, double na, double wavelengthNm) {
  const int steps = 20000;
  double sum = 0.0, sum2 = 0.0, area = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double s = na * (k + 0.5) / steps;
    const double w = delta * (1.0 - std::sqrt(1.0 - s * s));
    sum += w * s, sum2 += w * w * s, area += s;
  }
  const double mean = sum / area;
  return std::sqrt(sum2 / area - mean * mean) / (wavelengthNm * 1e-6);
}

// The Strehl ratio (the PSF's peak over the aberration-free one's) against
// the Marechal estimate exp(-(2 pi W_rms)^2), W_rms in waves.
TEST(Psf, DefocusStrehlFollowsMarechal) {
  const LensSystem lens = idealLens(8.0);
  const double wl = kWavelengthDNm, na = 1.0 / (2.0 * workingFNumber(8.0));
  const PsfModel model(lens, mono(lens, wl, 65, 4));
  for (const double target : {1.0 / 40.0, 1.0 / 20.0, 1.0 / 15.0}) {
    // Leading order W_rms = delta na^2 / (4 sqrt 3): the shift for the target.
    const double delta = target * wl * 1e-6 * 4.0 * std::sqrt(3.0) / (na * na);
    const double rms = defocusRmsWaves(delta, na, wl);
    const Psf psf = model.psf(delta);
    EXPECT_NEAR(psf.wavelengths[0].rmsWaves / rms, 1.0, 0.01) << "delta " << delta;
    const double marechal = std::exp(-std::pow(2.0 * kPi * rms, 2));
    EXPECT_NEAR(psf.strehl / marechal, 1.0, 0.02) << "W_rms " << rms << " waves";
  }
}

// Large aberrations: the PSF tends to the geometric spot (the rays'
// density), so its RMS radius tends to the spot diagram's. dgauss-50mm wide
// open (f/2), defocused, on the axis and 10 degrees off it (coma, astigmatism
// and the defocus). Also the PSF's centroid is the spot's: the mean of the
// transverse ray aberrations.
TEST(Psf, LargeAberrationsTendToTheGeometricSpot) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  const double film = focusFilmDistance(lens, kInfinity);
  for (const auto& [angle, shift] : {std::pair{0.0, 0.25}, std::pair{10.0, 0.3}}) {
    PsfSettings s;
    s.field = {angle, kInfinity};
    s.filmDistanceMm = film + shift;
    s.wavelengthsNm = {kWavelengthDNm};
    s.weights = {1.0};
    s.pupilSamples = 0;
    s.padding = 2;
    const Psf psf = PsfModel(lens, s).psf();
    const SpotDiagram spot = spotDiagram(lens, s.field, s.filmDistanceMm, 101);
    EXPECT_GT(psf.wavelengths[0].rmsWaves, 3.0);
    EXPECT_FALSE(psf.aliased());
    EXPECT_NEAR(psf.rmsRadiusMm() / spot.rmsRadiusMm, 1.0, 0.05);
    EXPECT_NEAR(psf.originMm.x + psf.centroidMm().x, spot.centroid.x, 0.05 * spot.rmsRadiusMm);
    EXPECT_NEAR(psf.originMm.y + psf.centroidMm().y, spot.centroid.y, 0.05 * spot.rmsRadiusMm);
  }
}

// A regular polygon of `blades` edges inscribed in the stop's circle, its
// first corner at `rotationDeg` from +x: inside when within every edge's
// half-plane (edge normals at rotation + (2k + 1) pi / blades).
StopTransmittance polygonStop(int blades, double rotationDeg, double circumradius) {
  return [=](double x, double y) {
    const double inradius = circumradius * std::cos(kPi / blades);
    for (int k = 0; k < blades; ++k) {
      const double normal = rotationDeg * kPi / 180.0 + (2 * k + 1) * kPi / blades;
      if (x * std::cos(normal) + y * std::sin(normal) > inradius) return 0.0;
    }
    return 1.0;
  };
}

// The PSF's angular power spectrum, 2-degree bins of the light between 10
// and 50 lambda N from the centre, and its spikes: bins that are the
// largest within +-8 degrees and above 4 times the median bin.
std::vector<double> spikeAnglesDeg(const Psf& psf, double lambdaN) {
  constexpr int kBins = 180;
  std::vector<double> bins(kBins, 0.0);
  for (int j = 0; j < psf.size; ++j)
    for (int i = 0; i < psf.size; ++i) {
      const Vec2d d = psf.offsetMm(i, j);
      const double r = std::hypot(d.x, d.y);
      if (r < 10.0 * lambdaN || r > 50.0 * lambdaN) continue;
      double angle = std::atan2(d.y, d.x) * 180.0 / kPi;
      if (angle < 0.0) angle += 360.0;
      bins[std::size_t(angle / 2.0) % kBins] += psf.at(i, j);
    }
  std::vector<double> sorted = bins;
  std::nth_element(sorted.begin(), sorted.begin() + kBins / 2, sorted.end());
  const double median = sorted[kBins / 2];
  std::vector<double> spikes;
  for (int b = 0; b < kBins; ++b) {
    bool peak = bins[std::size_t(b)] > 4.0 * median;
    for (int d = -4; d <= 4 && peak; ++d)
      if (d != 0 && bins[std::size_t((b + d + kBins) % kBins)] >= bins[std::size_t(b)]) peak = false;
    if (peak) spikes.push_back(2.0 * b + 1.0);
  }
  return spikes;
}

// Straight edges diffract light perpendicular to themselves: 6 blades give 6
// spikes (the edges' normals come in opposite pairs), 7 give 14 (each of
// the 7 normals, and opposite it by the PSF's symmetry), at the normals'
// angles: the stop's image in the exit pupil is the stop scaled (the sign
// turns it by 180 degrees, which leaves the spikes where they are). A
// rotation of 10 degrees, so a mirrored or transposed pupil moves them.
TEST(Psf, BladesGiveSpikesAlongTheirEdgesNormals) {
  constexpr double kRotationDeg = 10.0;
  for (const int blades : {6, 7}) {
    // The stop's circle holds the polygon's corners.
    const LensSystem lens = idealLens(8.0);
    PsfSettings s = mono(lens, kWavelengthDNm, 65, 8);
    s.stop = polygonStop(blades, kRotationDeg, lens.prescription().surfaces[0].apertureDiameter / 2.0);
    const Psf psf = PsfModel(lens, s).psf();
    const std::vector<double> spikes = spikeAnglesDeg(psf, kWavelengthDNm * 1e-6 * 8.0);
    const int expected = blades % 2 ? 2 * blades : blades;
    ASSERT_EQ(int(spikes.size()), expected) << blades << " blades";
    for (const double angle : spikes) {
      // The nearest edge normal, modulo pi / blades (odd) or 2 pi / blades.
      const double period = 360.0 / expected;
      const double phase = std::fmod(angle - kRotationDeg - 180.0 / blades + 720.0, period);
      EXPECT_LT(std::min(phase, period - phase), 3.0) << blades << " blades, spike at " << angle << " deg";
    }
  }
}

// A field the lens cannot reach: one InputError naming the lens.
TEST(Psf, AFieldBeyondTheLensCoverageIsRefused) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  PsfSettings s;
  s.field = {60.0, kInfinity};
  s.filmDistanceMm = focusFilmDistance(lens, kInfinity);
  try {
    PsfModel model(lens, s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "dgauss-50mm");
    EXPECT_NE(std::string(e.what()).find("coverage"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lensrt
