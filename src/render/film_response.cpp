#include "render/film_response.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"

namespace lensrt {

FilmResponse::FilmResponse(Info info, std::vector<Rgb> curves, std::vector<float> illuminant,
                           const std::function<double(double)>& samplingWeight)
    : info_(std::move(info)), curves_(std::move(curves)), illuminant_(std::move(illuminant)) {
  if (curves_.size() != std::size_t(kSamples) || illuminant_.size() != std::size_t(kSamples))
    throw std::invalid_argument("FilmResponse: tables must have one entry per nm over 360-830 nm");
  // What the film records of white light per 1 nm bin, with a floor so that
  // every wavelength the film sees can be drawn; its CDF, then its quantiles.
  std::vector<double> weights(std::size_t(kSamples - 1));
  double largest = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const float nm = kMinNm + float(i) + 0.5f;
    const Rgb c = curve(nm);
    weights[i] = samplingWeight
                     ? samplingWeight(nm)
                     : double(std::abs(c.x) + std::abs(c.y) + std::abs(c.z)) * this->illuminant(nm);
    largest = std::max(largest, weights[i]);
  }
  if (!(largest > 0) || !std::isfinite(largest))
    throw std::invalid_argument("FilmResponse: the film records no light");
  std::vector<double> cdf(weights.size() + 1, 0.0);
  for (std::size_t i = 0; i < weights.size(); ++i) cdf[i + 1] = cdf[i] + weights[i] + 1e-4 * largest;
  quantiles_.resize(kQuantiles + 1);
  std::size_t bin = 0;
  for (int k = 0; k <= kQuantiles; ++k) {
    const double target = cdf.back() * k / kQuantiles;
    while (bin + 1 < weights.size() && cdf[bin + 1] < target) ++bin;
    const double t = std::clamp((target - cdf[bin]) / (cdf[bin + 1] - cdf[bin]), 0.0, 1.0);
    quantiles_[std::size_t(k)] = float(kMinNm + double(bin) + t);
  }
  quantiles_.front() = kMinNm;
  quantiles_.back() = kMaxNm;
}

namespace {

// Linear interpolation in a 1 nm table starting at kMinNm.
template <class T>
T interpolate(const std::vector<T>& table, float nm) {
  const float x = nm - FilmResponse::kMinNm;
  if (!(x >= 0 && x <= float(FilmResponse::kSamples - 1))) return T{} * 0.0f;
  const int i = std::min(int(x), FilmResponse::kSamples - 2);
  const float t = x - float(i);
  return table[std::size_t(i)] * (1 - t) + table[std::size_t(i) + 1] * t;
}

std::vector<float> d65AtYOne() {
  const double whiteY = spectrumToXyz([](double nm) { return d65(nm); }).y;
  std::vector<float> illuminant(static_cast<std::size_t>(FilmResponse::kSamples));
  for (std::size_t i = 0; i < illuminant.size(); ++i)
    illuminant[i] = float(d65(FilmResponse::kMinNm + double(i)) / whiteY);
  return illuminant;
}

}  // namespace

FilmResponse FilmResponse::make(Info info, const std::function<Vec3d(double)>& sensor, const Mat3d& toOutput,
                                const std::function<double(double)>& neutral, const Vec3d& neutralTarget,
                                const std::function<double(double)>& samplingWeight) {
  std::vector<Vec3d> rgb(static_cast<std::size_t>(kSamples));
  std::vector<double> white(static_cast<std::size_t>(kSamples));
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    const double nm = kMinNm + double(i);
    rgb[i] = toOutput * sensor(nm);
    white[i] = neutral(nm);
  }
  // What the film records of the neutral white, integrated as the renderer's
  // samples integrate it.
  const Vec3d recorded =
      FilmResponse::recorded([&rgb](double nm) { return rgb[static_cast<std::size_t>(nm - kMinNm)]; },
                             [&white](double nm) { return white[static_cast<std::size_t>(nm - kMinNm)]; });
  const Vec3d scale{neutralTarget.x / recorded.x, neutralTarget.y / recorded.y, neutralTarget.z / recorded.z};
  if (!std::isfinite(scale.x) || !std::isfinite(scale.y) || !std::isfinite(scale.z))
    throw std::invalid_argument("FilmResponse: the film records no white in some channel");
  std::vector<Rgb> curves(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) curves[i] = Rgb(rgb[i] * scale);
  FilmResponse film(std::move(info), std::move(curves), d65AtYOne(), samplingWeight);
  film.sensorToOutput_ = Mat3d::diagonal(scale) * toOutput;
  return film;
}

Vec3d FilmResponse::recorded(const std::function<Vec3d(double)>& curves,
                             const std::function<double(double)>& light) {
  // Exact for the product of two linear pieces on each 1 nm step.
  Vec3d sum{0, 0, 0};
  for (int i = 0; i + 1 < kSamples; ++i) {
    const double nm = kMinNm + double(i);
    const Vec3d s0 = curves(nm), s1 = curves(nm + 1);
    const double a = light(nm), b = light(nm + 1);
    sum += (s0 * (2 * a + b) + s1 * (a + 2 * b)) / 6.0;
  }
  return sum;
}

namespace {

FilmResponse makeCie1931Srgb() {
  const ColorSpace& srgb = colorSpace(ColorSpaceId::Srgb);
  const double whiteY = spectrumToXyz([](double nm) { return d65(nm); }).y;
  // The tabulated D65 is the sRGB white within 1e-4 in chromaticity: the
  // per-channel scale makes it record exactly (1, 1, 1) (the white furnace).
  return FilmResponse::make(
      {"cie1931", "none", "srgb", "0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329"},
      [](double nm) { return cieXyzMatching(nm) / kCieYIntegral; }, srgb.xyzToRgb,
      [whiteY](double nm) { return d65(nm) / whiteY; }, {1, 1, 1}, FilmResponse::cie1931SamplingWeight);
}

}  // namespace

double FilmResponse::cie1931SamplingWeight(double nm) {
  const Vec3d c = colorSpace(ColorSpaceId::Srgb).xyzToRgb * cieXyzMatching(nm);
  return (std::abs(c.x) + std::abs(c.y) + std::abs(c.z)) * d65(nm);
}

std::string FilmResponse::describe() const {
  std::string s = info_.response;
  if (info_.whiteBalance != "none") s += ",wb=" + info_.whiteBalance;
  if (info_.outputSpace != "srgb") s += ",output=" + info_.outputSpace;
  return s;
}

const FilmResponse& FilmResponse::cie1931Srgb() {
  static const FilmResponse response = makeCie1931Srgb();
  return response;
}

Rgb FilmResponse::curve(float nm) const {
  return interpolate(curves_, nm);
}

float FilmResponse::illuminant(float nm) const {
  return interpolate(illuminant_, nm);
}

float FilmResponse::wavelengthPdf(float nm) const {
  if (!(nm >= kMinNm && nm <= kMaxNm)) return 0.0f;
  const auto k = std::size_t(std::clamp<std::ptrdiff_t>(
      std::upper_bound(quantiles_.begin(), quantiles_.end(), nm) - quantiles_.begin() - 1, 0,
      kQuantiles - 1));
  return 1.0f / (float(kQuantiles) * (quantiles_[k + 1] - quantiles_[k]));
}

}  // namespace lensrt
