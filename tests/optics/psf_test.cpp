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

TEST(Psf, Explore) {
  for (const double wl : {kWavelengthFNm, kWavelengthDNm, kWavelengthCNm}) {
    const LensSystem lens = idealLens(16.0);
    const PsfModel model(lens, mono(lens, wl, 65, 8));
    const Psf psf = model.psf();
    const double n = lens.paraxial().fNumber;
    const double zero = firstZeroMm(psf);
    const double expected = 1.21967 * wl * 1e-6 * n;
    const double ee = encircledEnergy(psf, expected);
    std::printf("wl %.1f N %.4f size %d pix %.3g zero %.6g expected %.6g ratio %.5f EE %.5f rms %.3g strehl %.6f\n", wl, n,
                psf.size, psf.pixelMm, zero, expected, zero / expected, ee, psf.wavelengths[0].rmsWaves, psf.strehl);
    const MtfSamples m = mtfSamples(psf);
    const double cutoff = 1.0 / (wl * 1e-6 * n);
    double worst = 0.0;
    for (std::size_t k = 0; k < m.tangential.size(); ++k) {
      const double f = k * m.stepPerMm;
      worst = std::max({worst, std::abs(m.tangential[k] - diffractionLimitedMtf(f, cutoff)),
                        std::abs(m.sagittal[k] - diffractionLimitedMtf(f, cutoff))});
    }
    const PupilFunction pf = model.pupilFunction();
    std::printf("extent %.6f %.6f spacing %.6g n %d\n", psf.wavelengths[0].extent.x, psf.wavelengths[0].extent.y, pf.grid.spacing, pf.grid.size());
    for (int i = 0; i < pf.grid.size(); ++i) std::printf("%.3f ", pf.amplitude[std::size_t(pf.grid.half * pf.grid.size() + i)]);
    std::printf("\n");
    {
      const int c = psf.size / 2;
      double pix = 0.0;
      for (int j = 0; j < psf.size; ++j)
        for (int i = 0; i < psf.size; ++i)
          if (std::hypot(psf.offsetMm(i, j).x, psf.offsetMm(i, j).y) < expected) pix += psf.at(i, j);
      std::printf("pixel EE %.5f\n", pix);
      for (int k = 0; k < 14; ++k) {
        const double v = kPi * k * psf.pixelMm / (wl * 1e-6 * n);
        const double airy = k == 0 ? 1.0 : std::pow(2.0 * std::cyl_bessel_j(1.0, v) / v, 2);
        std::printf("%d %.5f %.5f\n", k, psf.at(c + k, c) / psf.at(c, c), airy);
      }
    }
    std::printf("  mtf worst %.5f cutoff %.1f step %.3f\n", worst, cutoff, m.stepPerMm);
  }
}

}  // namespace
}  // namespace lensrt
