#include "optics/psf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/constants.h"
#include "core/error.h"
#include "optics/fft.h"

namespace lensrt {

struct PsfModel::Wavelength {
  double wavelengthNm = 0.0;
  double weight = 0.0;
  PupilRays rays;
};

namespace {

constexpr int kAutoFirstHalf = 32;  // 65 samples across the pupil
constexpr int kAutoMaxHalf = 256;   // 513
constexpr double kAutoMaxStepWaves = 0.25;

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

void checkSettings(const PsfSettings& s) {
  if (s.wavelengthsNm.empty()) throw std::invalid_argument("the PSF needs at least one wavelength");
  if (s.weights.size() != s.wavelengthsNm.size())
    throw std::invalid_argument("the PSF needs one weight per wavelength");
  double sum = 0.0;
  for (std::size_t k = 0; k < s.weights.size(); ++k) {
    if (!(s.wavelengthsNm[k] >= 200.0 && s.wavelengthsNm[k] <= 2000.0))
      throw std::invalid_argument("a wavelength must be within 200-2000 nm");
    if (!(s.weights[k] >= 0.0) || !std::isfinite(s.weights[k]))
      throw std::invalid_argument("a wavelength's weight must be finite and >= 0");
    sum += s.weights[k];
  }
  if (!(sum > 0.0)) throw std::invalid_argument("the wavelengths' weights are all 0");
  if (s.pupilSamples != 0 && (s.pupilSamples < 9 || s.pupilSamples > 2049 || s.pupilSamples % 2 == 0))
    throw std::invalid_argument("pupil samples must be odd, 9-2049 (or 0: automatic)");
  if (s.padding < 2 || s.padding > 32) throw std::invalid_argument("the padding must be 2-32");
}

}  // namespace

PsfModel::~PsfModel() = default;
PsfModel::PsfModel(PsfModel&&) noexcept = default;

PsfModel::PsfModel(const LensSystem& lens, PsfSettings settings)
    : lens_(lens), settings_(std::move(settings)) {
  checkSettings(settings_);
  const PsfSettings& s = settings_;
  const std::string& name = lens.prescription().name;
  std::vector<PupilBeam> beams;
  for (const double wl : s.wavelengthsNm) {
    const auto beam = pupilBeam(lens, s.field, wl);
    if (!beam)
      throw InputError(name, "the field at " + shortNumber(s.field.angleDeg) +
                                 " deg is beyond the lens's coverage: its chief ray does not pass at " +
                                 shortNumber(wl) + " nm");
    beams.push_back(*beam);
  }
  primaryBeam_ = beams.front();
  double halfWidth = 0.0;
  for (const PupilBeam& b : beams) halfWidth = std::max(halfWidth, b.halfWidth);
  const double shortest = *std::min_element(s.wavelengthsNm.begin(), s.wavelengthsNm.end());
  const double totalWeight = std::accumulate(s.weights.begin(), s.weights.end(), 0.0);
  // The grid: `half` spacings on each side of the chief ray at the shortest
  // wavelength; the others' spacing scales with the wavelength so every PSF
  // shares the film grid (fewer samples across their pupil).
  for (int half = s.pupilSamples ? (s.pupilSamples - 1) / 2 : kAutoFirstHalf;; half *= 2) {
    const double spacing = halfWidth / half;
    pupilSamples_ = 2 * half + 1;
    fftSize_ = fftFriendlySize(std::max(2 * pupilSamples_, s.padding * (pupilSamples_ - 1)));
    pixelMm_ = shortest * 1e-6 / (fftSize_ * spacing);
    wavelengths_.clear();
    double maxStep = 0.0;
    const ReferenceSphere reference = referenceSphere(lens, primaryBeam_, lens.rearZ() + s.filmDistanceMm);
    for (std::size_t k = 0; k < s.wavelengthsNm.size(); ++k) {
      const double wl = s.wavelengthsNm[k];
      PupilGrid grid;
      grid.spacing = wl * 1e-6 / (fftSize_ * pixelMm_);
      grid.half = int(std::ceil(halfWidth / grid.spacing - 1e-9));
      grid.centre = {beams[k].chiefDirection.x, beams[k].chiefDirection.y};
      wavelengths_.push_back(
          {wl, s.weights[k] / totalWeight, PupilRays(lens, s.field, wl, beams[k], grid, s.stop)});
      maxStep = std::max(maxStep, wavelengths_.back().rays.at(reference).maxStepWaves);
    }
    if (s.pupilSamples || maxStep < kAutoMaxStepWaves || half * 2 > kAutoMaxHalf) break;
  }
}

PupilFunction PsfModel::pupilFunction(double filmShiftMm) const {
  const double filmZ = lens_.rearZ() + settings_.filmDistanceMm + filmShiftMm;
  return wavelengths_.front().rays.at(referenceSphere(lens_, primaryBeam_, filmZ));
}

Psf PsfModel::psf(double filmShiftMm) const {
  const double filmZ = lens_.rearZ() + settings_.filmDistanceMm + filmShiftMm;
  const ReferenceSphere reference = referenceSphere(lens_, primaryBeam_, filmZ);
  Psf psf;
  const int m = fftSize_;
  psf.size = m;
  psf.pixelMm = pixelMm_;
  psf.originMm = {reference.centre.x, reference.centre.y};
  psf.pupilSamples = pupilSamples_;
  psf.padding = settings_.padding;
  const std::size_t count = std::size_t(m) * std::size_t(m);
  psf.intensity.assign(count, 0.0);
  psf.limit.assign(count, 0.0);
  ComplexGrid field(m);
  double limitPeak = 0.0;
  for (const Wavelength& w : wavelengths_) {
    const PupilFunction pupil = w.rays.at(reference);
    const int n = pupil.grid.size();
    PsfWavelength info;
    info.wavelengthNm = w.wavelengthNm;
    info.weight = w.weight;
    info.pupilSamples = n;
    info.pupilSpacing = pupil.grid.spacing;
    info.rmsWaves = pupil.rmsWaves;
    info.peakToValleyWaves = pupil.peakToValleyWaves;
    info.maxStepWaves = pupil.maxStepWaves;
    psf.maxStepWaves = std::max(psf.maxStepWaves, pupil.maxStepWaves);
    // The pupil's lit extent, for the MTF's cutoff.
    int loI = n, hiI = -1, loJ = n, hiJ = -1;
    double energy = 0.0, sumAmplitude = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = pupil.amplitude[std::size_t(j) * std::size_t(n) + std::size_t(i)];
        if (!(a > 0.0)) continue;
        loI = std::min(loI, i), hiI = std::max(hiI, i), loJ = std::min(loJ, j), hiJ = std::max(hiJ, j);
        energy += a * a;
        sumAmplitude += a;
      }
    if (!(energy > 0.0)) throw std::invalid_argument("no light passes the stop's shape at this field");
    info.extent = {(hiI - loI + 1) * pupil.grid.spacing, (hiJ - loJ + 1) * pupil.grid.spacing};
    const double waveMm = w.wavelengthNm * 1e-6;
    psf.cutoffPerMm.x = std::max(psf.cutoffPerMm.x, info.extent.x / waveMm);
    psf.cutoffPerMm.y = std::max(psf.cutoffPerMm.y, info.extent.y / waveMm);
    // U(x) = sum a exp(i 2 pi (W + (L dx + M dy) / lambda)): FFTW's backward
    // (+i) transform, the pupil in the array's corner (its offset is a phase
    // per PSF sample, gone in |U|^2), the intensity over m^2 sum a^2 (by
    // Parseval, `energy` in the window) over the pupil's light.
    const double unit = 1.0 / (double(m) * double(m) * pupil.light);
    double ownPeak = 0.0;
    for (const bool withOpd : {true, false}) {
      field.clear();
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const std::size_t k = std::size_t(j) * std::size_t(n) + std::size_t(i);
          if (!(pupil.amplitude[k] > 0.0)) continue;
          const double phase = withOpd ? 2.0 * kPi * pupil.opdWaves[k] : 0.0;
          field(i, j) = std::polar(pupil.amplitude[k], phase);
        }
      field.transform(+1);
      std::vector<double>& out = withOpd ? psf.intensity : psf.limit;
      // Shift so that dx = 0 is sample m/2.
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const double value = std::norm(field(i, j)) * unit;
          if (withOpd) ownPeak = std::max(ownPeak, value);
          out[std::size_t((j + m / 2) % m) * std::size_t(m) + std::size_t((i + m / 2) % m)] +=
              value * w.weight;
        }
    }
    // The diffraction limit's peak: all amplitudes in phase at dx = 0.
    const double peak = sumAmplitude * sumAmplitude * unit;
    limitPeak += w.weight * peak;
    info.strehl = ownPeak / peak;
    psf.wavelengths.push_back(info);
  }
  psf.windowLight = std::accumulate(psf.intensity.begin(), psf.intensity.end(), 0.0);
  psf.strehl = *std::max_element(psf.intensity.begin(), psf.intensity.end()) / limitPeak;
  return psf;
}

}  // namespace lensrt

namespace lensrt {

Vec2d Psf::centroidMm() const {
  Vec2d sum;
  double total = 0.0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      sum = sum + offsetMm(i, j) * at(i, j);
      total += at(i, j);
    }
  return total > 0.0 ? sum / total : Vec2d{};
}

double Psf::rmsRadiusMm() const {
  const Vec2d c = centroidMm();
  double sum = 0.0, total = 0.0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const Vec2d d = offsetMm(i, j) - c;
      sum += (d.x * d.x + d.y * d.y) * at(i, j);
      total += at(i, j);
    }
  return total > 0.0 ? std::sqrt(sum / total) : 0.0;
}

ComplexGrid psfSpectrum(const Psf& psf, bool limit) {
  const int m = psf.size;
  const std::vector<double>& values = limit ? psf.limit : psf.intensity;
  ComplexGrid spectrum(m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) spectrum(i, j) = values[std::size_t(j) * std::size_t(m) + std::size_t(i)];
  spectrum.transform(-1);
  return spectrum;
}

std::vector<double> encircledEnergy(const Psf& psf, const std::vector<double>& radiiMm, Vec2d centreMm,
                                    bool limit) {
  // The sampled intensity I_m is the trigonometric series sum_k C_k
  // exp(2 pi i nu_k.x) (band-limited: its spectrum, the OTF, lies within the
  // grid's frequencies), whose integral over a disc of radius r about c is
  // sum_k C_k exp(2 pi i nu_k.c) r J1(2 pi r |nu_k|) / |nu_k| (pi r^2 at 0).
  // The Bessel factor depends on |k|^2 alone: the terms are summed per
  // |k|^2 first, so each radius costs one J1 per distinct |k|^2.
  const int m = psf.size;
  const ComplexGrid spectrum = psfSpectrum(psf, limit);
  const double window = m * psf.pixelMm;
  std::vector<double> byNorm(std::size_t(m / 2 + 1) * std::size_t(m / 2 + 1) * 2, 0.0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      // Frequencies symmetric about 0; the samples start at offset -m/2 pixels.
      const int ki = i <= m / 2 ? i : i - m, kj = j <= m / 2 ? j : j - m;
      const Vec2d nu{ki / window, kj / window};
      const double shift =
          2.0 * kPi * (nu.x * (centreMm.x + m / 2 * psf.pixelMm) + nu.y * (centreMm.y + m / 2 * psf.pixelMm));
      byNorm[std::size_t(ki * ki + kj * kj)] += std::real(spectrum(i, j) * std::polar(1.0, shift));
    }
  std::vector<double> out;
  for (const double r : radiiMm) {
    double inside = byNorm[0] * kPi * r * r;
    for (std::size_t q = 1; q < byNorm.size(); ++q) {
      if (byNorm[q] == 0.0) continue;
      const double rho = std::sqrt(double(q)) / window;
      inside += byNorm[q] * r * std::cyl_bessel_j(1.0, 2.0 * kPi * r * rho) / rho;
    }
    // The samples are light per sample, so the integral is light times the
    // sample area; m^2 from the unnormalised transform. A fraction of the
    // field's whole light, not of the window's.
    out.push_back(inside / (window * window));
  }
  return out;
}

double encircledEnergy(const Psf& psf, double radiusMm, Vec2d centreMm, bool limit) {
  return encircledEnergy(psf, std::vector<double>{radiusMm}, centreMm, limit).front();
}

}  // namespace lensrt
