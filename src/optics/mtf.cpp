#include "optics/mtf.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "optics/fft.h"

namespace lensrt {

MtfSamples mtfSamples(const Psf& psf, bool limit) {
  const int m = psf.size;
  const ComplexGrid spectrum = psfSpectrum(psf, limit);
  MtfSamples s;
  s.stepPerMm = 1.0 / (m * psf.pixelMm);
  // The PSF's samples are fractions of the whole light, so the spectrum is
  // the OTF as it is (1 at zero frequency, where the window's sum is a
  // little less: the light beyond the window is at the highest frequencies).
  s.tangential.push_back(1.0);
  s.sagittal.push_back(1.0);
  for (int k = 1; k <= m / 2; ++k) {
    s.tangential.push_back(std::abs(spectrum(k, 0)));
    s.sagittal.push_back(std::abs(spectrum(0, k)));
  }
  return s;
}

namespace {

double interpolate(const std::vector<double>& values, double step, double frequency) {
  const double x = frequency / step;
  const auto k = std::size_t(x);
  if (k + 1 >= values.size()) return 0.0;
  const double f = x - double(k);
  return values[k] * (1.0 - f) + values[k + 1] * f;
}

}  // namespace

MtfCurves mtfCurves(const Psf& psf, double maxFrequencyPerMm, int points) {
  const MtfSamples mtf = mtfSamples(psf), limit = mtfSamples(psf, true);
  MtfCurves c;
  for (int k = 0; k < points; ++k) {
    const double f = points > 1 ? maxFrequencyPerMm * k / (points - 1) : 0.0;
    c.frequencyPerMm.push_back(f);
    c.tangential.push_back(interpolate(mtf.tangential, mtf.stepPerMm, f));
    c.sagittal.push_back(interpolate(mtf.sagittal, mtf.stepPerMm, f));
    c.limitTangential.push_back(interpolate(limit.tangential, limit.stepPerMm, f));
    c.limitSagittal.push_back(interpolate(limit.sagittal, limit.stepPerMm, f));
  }
  return c;
}

ThroughFocusMtf throughFocusMtf(const PsfModel& model, double frequencyPerMm,
                                const std::vector<double>& shifts) {
  ThroughFocusMtf t;
  t.frequencyPerMm = frequencyPerMm;
  t.filmShiftMm = shifts;
  for (const double shift : shifts) {
    const MtfCurves c = mtfCurves(model.psf(shift), frequencyPerMm, 2);
    t.tangential.push_back(c.tangential[1]);
    t.sagittal.push_back(c.sagittal[1]);
    t.limit.push_back(std::max(c.limitTangential[1], c.limitSagittal[1]));
  }
  return t;
}

double diffractionLimitedMtf(double frequency, double cutoff) {
  if (!(frequency < cutoff)) return 0.0;
  const double phi = std::acos(std::max(0.0, frequency) / cutoff);
  return 2.0 / kPi * (phi - std::cos(phi) * std::sin(phi));
}

}  // namespace lensrt
