// What the film records of each wavelength under spectral transport: three
// response curves c(l) already in the output space's RGB, so that a pixel is
// the integral of c(l) L(l) dl (the CIE 1931 observer, or a camera's
// curves times its colour matrix), and the illuminant that RGB (1, 1, 1)
// light stands for. Tabulated at 1 nm over 360-830 nm and interpolated
// linearly. Wavelengths are drawn in proportion to what the film records of
// white light, (|c_R| + |c_G| + |c_B|)(l) times the illuminant: for the CIE
// observer in sRGB this halves the colour noise of pbrt-v4's visible-range
// density (1 / cosh^2(0.0072 (l - 538 nm))), whose tail leaves blue with a
// per-sample deviation of 58% on white (32% here). The density is sampled
// through 1024 quantiles of it, linear between them: O(1) per wavelength, and
// the density is exactly that of the sampling (constant between quantiles).
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "core/mat3.h"
#include "core/vec.h"

namespace lensrt {

class FilmResponse {
 public:
  static constexpr float kMinNm = 360.0f, kMaxNm = 830.0f;
  static constexpr int kSamples = 471;  // 1 nm

  // What a render records about its colour (metadata and identity).
  struct Info {
    std::string response = "cie1931";   // the sensor's curves
    std::string whiteBalance = "none";  // "none", or the white adapted from
    std::string outputSpace = "srgb";   // the RGB the curves give
    std::string chromaticities;         // OpenEXR's 8 numbers for it; empty: none (camera RGB)
  };

  // curves[i], illuminant[i]: at kMinNm + i nm. The illuminant is normalised
  // to luminance Y = 1 (the white of RGB (1, 1, 1) light).
  // samplingWeight: the density wavelengths are drawn from, up to a factor
  // (none: |c_R| + |c_G| + |c_B| times the illuminant).
  FilmResponse(Info info, std::vector<Rgb> curves, std::vector<float> illuminant,
               const std::function<double(double)>& samplingWeight = {});

  // Curves from a sensor's three curves s(l) (the CIE observer's xbar, ybar,
  // zbar over their ybar integral, or a camera's) mapped by `toOutput`, then
  // scaled per channel so that a reflectance of 1 under `neutral` (a
  // spectrum with Y = 1) records `neutralTarget` exactly, as the renderer
  // integrates (the product of the linearly interpolated tables). The light
  // of RGB (1, 1, 1) is D65 at Y = 1.
  // Wavelengths are drawn by `samplingWeight`, which a caller keeps the same
  // across white balances and output spaces so that renders differing only
  // in those trace the same paths.
  static FilmResponse make(Info info, const std::function<Vec3d(double)>& sensor, const Mat3d& toOutput,
                           const std::function<double(double)>& neutral, const Vec3d& neutralTarget,
                           const std::function<double(double)>& samplingWeight);
  // What curves record of a light: the integral over [kMinNm, kMaxNm] of
  // the product of the two tables linearly interpolated between whole nm,
  // as the renderer's samples integrate it.
  static Vec3d recorded(const std::function<Vec3d(double)>& curves,
                        const std::function<double(double)>& light);
  // The CIE observer's sampling weight: its linear sRGB curves'
  // |r| + |g| + |b| under D65, whatever the output space or white balance.
  static double cie1931SamplingWeight(double nm);

  // The CIE 1931 observer into linear Rec. 709 (sRGB) RGB under D65: a
  // reflectance of 1 lit by RGB (1, 1, 1) records (1, 1, 1) exactly.
  static const FilmResponse& cie1931Srgb();

  const Info& info() const { return info_; }
  // The matrix from the sensor's curves to the film's (make's `toOutput`
  // with its per-channel scale): a pixel is this matrix times the sensor's
  // integrals of the light, so its inverse gives the sensor's own reading
  // back (the identity for a film built from its curves directly).
  const Mat3d& sensorToOutput() const { return sensorToOutput_; }
  // "cie1931" or "cie1931,wb=5000K,output=acescg": the parts that differ from the defaults.
  std::string describe() const;
  Rgb curve(float nm) const;         // 0 outside the range
  float illuminant(float nm) const;  // 0 outside the range

  struct WavelengthDraw {
    float nm = 550, pdf = 0;  // pdf per nm
  };
  // u in [0, 1) -> a wavelength in [kMinNm, kMaxNm] and its density.
  WavelengthDraw sampleWavelength(float u) const {
    const float x = u * float(kQuantiles);
    const int k = std::min(int(x), kQuantiles - 1);
    const float lo = quantiles_[std::size_t(k)], width = quantiles_[std::size_t(k) + 1] - lo;
    return {lo + (x - float(k)) * width, 1.0f / (float(kQuantiles) * width)};
  }
  // The density at a wavelength (0 outside the range).
  float wavelengthPdf(float nm) const;

 private:
  Info info_;
  Mat3d sensorToOutput_;
  std::vector<Rgb> curves_;
  std::vector<float> illuminant_;
  static constexpr int kQuantiles = 1024;
  std::vector<float> quantiles_;  // kQuantiles + 1 wavelengths, from kMinNm to kMaxNm
};

}  // namespace lensrt
