#include "render/wavelengths.h"

#include <algorithm>
#include <cmath>

#include "color/rgb_to_spectrum.h"
#include "render/film_response.h"

namespace lensrt {

SampledWavelengths SampledWavelengths::sample(float u, const FilmResponse& response) {
  SampledWavelengths s;
  s.spectral_ = true;
  for (std::size_t i = 0; i < Spectrum::kLanes; ++i) {
    // The hero and three copies a quarter of the density's range apart.
    float ui = u + float(i) / float(Spectrum::kLanes);
    if (ui >= 1.0f) ui -= 1.0f;
    const FilmResponse::WavelengthDraw draw = response.sampleWavelength(ui);
    s.nm_[i] = draw.nm;
    s.illuminant_[i] = response.illuminant(draw.nm);
    s.plainWeight_[i] = response.curve(draw.nm) / (float(Spectrum::kLanes) * draw.pdf);
  }
  s.filmWeight_ = s.plainWeight_;
  return s;
}

void SampledWavelengths::terminateSecondary() {
  if (!spectral_ || terminated_) return;
  terminated_ = true;
  filmWeight_[0] = plainWeight_[0] * float(Spectrum::kLanes);
  for (std::size_t i = 1; i < Spectrum::kLanes; ++i) filmWeight_[i] = Rgb{0, 0, 0};
}

void SampledWavelengths::weightLanes(const std::array<float, Spectrum::kLanes>& factors) {
  if (!spectral_ || terminated_) return;
  for (std::size_t i = 0; i < Spectrum::kLanes; ++i) {
    filmWeight_[i] = plainWeight_[i] * factors[i];
    live_[i] = factors[i] > 0.0f ? 1.0f : 0.0f;
  }
}

Rgb SampledWavelengths::toFilm(const Spectrum& radiance) const {
  if (!spectral_) return radiance.rgb();
  Rgb sum{0, 0, 0};
  for (std::size_t i = 0; i < Spectrum::kLanes; ++i) sum += filmWeight_[i] * radiance[i];
  return sum;
}

namespace {

// A colour in [0, 1]^3 as its smooth spectrum's values at the lanes' wavelengths.
Spectrum smoothSpectrum(const Rgb& c, const std::array<float, Spectrum::kLanes>& nm) {
  // A grey's spectrum is flat (the table's own solution, without its rounding).
  if (c.x == c.y && c.y == c.z) return Spectrum(c.x);
  const SigmoidPolynomial s = RgbToSpectrumTable::srgb()(c);
  return {s(nm[0]), s(nm[1]), s(nm[2]), s(nm[3])};
}

Rgb clamp01(const Rgb& c) {
  const auto f = [](float x) { return std::clamp(x, 0.0f, 1.0f); };  // NaN -> NaN, kept visible
  return {f(c.x), f(c.y), f(c.z)};
}

}  // namespace

Spectrum SampledWavelengths::upsampleReflectance(const Rgb& c) const {
  return smoothSpectrum(clamp01(c), nm_);
}

// Above 1, pbrt-v4's RGBUnboundedSpectrum: the colour scaled by 1 / (2 max)
// into the table, and its spectrum scaled back.
Spectrum SampledWavelengths::upsampleUnbounded(const Rgb& c) const {
  const Rgb positive = max(c, Rgb{0, 0, 0});
  const float m = maxComponent(positive);
  if (!(m > 1.0f)) return smoothSpectrum(clamp01(positive), nm_);
  const float scale = 2 * m;
  return smoothSpectrum(positive / scale, nm_) * scale;
}

// pbrt-v4's RGBIlluminantSpectrum: the scaled smooth spectrum times the
// white's illuminant, so (1, 1, 1) is the illuminant itself.
Spectrum SampledWavelengths::upsampleIlluminant(const Rgb& c) const {
  const Rgb positive = max(c, Rgb{0, 0, 0});
  const float m = maxComponent(positive);
  if (!(m > 0)) return Spectrum(0.0f);
  const float scale = 2 * m;
  return smoothSpectrum(positive / scale, nm_) * illuminant_ * scale;
}

}  // namespace lensrt
