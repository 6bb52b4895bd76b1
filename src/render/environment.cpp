#include "render/environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/constants.h"

namespace lensrt {

Environment Environment::constant(const Rgb& radiance) {
  Environment e;
  e.constant_ = radiance;
  e.black_ = !(maxComponent(radiance) > 0);
  e.averageLuminance_ = luminance(radiance);
  e.averageRadiance_ = radiance;
  e.description_ = "constant " + std::to_string(radiance.x) + "," + std::to_string(radiance.y) + "," +
                   std::to_string(radiance.z);
  return e;
}

Environment Environment::latLong(const Image& image) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  int grey = r >= 0 ? r : (image.channelIndex("Y") >= 0 ? image.channelIndex("Y") : -1);
  if (grey < 0 && image.channelCount() > 0) grey = 0;
  if (grey < 0 || image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("environment map has no channels");
  Environment e;
  e.width_ = image.width;
  e.height_ = image.height;
  e.texels_.resize(std::size_t(e.width_) * e.height_);
  std::vector<float> weights(e.texels_.size());
  double sumLum = 0, sumSin = 0;
  Vec3d sumRgb{0, 0, 0};
  for (int y = 0; y < e.height_; ++y) {
    const float sinTheta = std::sin(kPiF * (float(y) + 0.5f) / float(e.height_));
    for (int x = 0; x < e.width_; ++x) {
      Rgb c;
      if (r >= 0 && g >= 0 && b >= 0)
        c = {image.at(x, y, r), image.at(x, y, g), image.at(x, y, b)};
      else
        c = Rgb{1, 1, 1} * image.at(x, y, grey);
      // Non-finite or negative texels would poison every estimate: treat as black.
      for (int k = 0; k < 3; ++k)
        if (!(std::isfinite(c[k]) && c[k] > 0)) c[k] = 0;
      const std::size_t i = std::size_t(y) * e.width_ + x;
      e.texels_[i] = c;
      weights[i] = luminance(c) * sinTheta;
      // Rows near the poles cover less solid angle.
      sumLum += double(luminance(c)) * sinTheta;
      sumRgb += Vec3d(c) * double(sinTheta);
      sumSin += sinTheta;
    }
  }
  e.distribution_ = Distribution2D(weights, e.width_, e.height_);
  e.black_ = e.distribution_.empty();
  e.averageLuminance_ = sumSin > 0 ? float(sumLum / sumSin) : 0.0f;
  e.averageRadiance_ = sumSin > 0 ? Rgb(sumRgb / sumSin) : Rgb{0, 0, 0};
  e.description_ = "latlong " + std::to_string(e.width_) + "x" + std::to_string(e.height_);
  e.findSun();
  return e;
}

void Environment::findSun() {
  sunTexels_.clear();
  sunPick_ = Distribution1D();
  float brightest = 0;
  for (const Rgb& t : texels_) brightest = std::max(brightest, luminance(t));
  if (!(brightest > 0)) return;
  // A texel of row y covers 2 pi / width x (cos theta0 - cos theta1) sr.
  const auto solidAngle = [&](int y) {
    return 2 * kPi / width_ * (std::cos(kPi * double(y) / height_) - std::cos(kPi * double(y + 1) / height_));
  };
  double covered = 0;
  std::vector<float> weights;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::size_t i = std::size_t(y) * width_ + x;
      const float l = luminance(texels_[i]);
      if (!(l >= kSunFraction * brightest)) continue;
      covered += solidAngle(y);
      if (covered > kSunSolidAngle) {  // wide: no sun
        sunTexels_.clear();
        return;
      }
      sunTexels_.push_back(std::uint32_t(i));
      weights.push_back(float(l * solidAngle(y)));
    }
  sunPick_ = Distribution1D(weights);
  if (sunPick_.empty()) sunTexels_.clear();
}

std::size_t Environment::texelOf(const Vec3f& world) const {
  const Vec2f uv = directionToUv(toMap(world));
  const int x = std::min(int(uv.x * float(width_)), width_ - 1);
  const int y = std::min(int(uv.y * float(height_)), height_ - 1);
  return std::size_t(y) * width_ + x;
}

bool Environment::inSun(const Vec3f& direction) const {
  return hasSun() && std::binary_search(sunTexels_.begin(), sunTexels_.end(), texelOf(direction));
}

float Environment::pdfSun(const Vec3f& direction) const {
  if (!hasSun()) return 0;
  const auto it = std::lower_bound(sunTexels_.begin(), sunTexels_.end(), texelOf(direction));
  if (it == sunTexels_.end() || *it != texelOf(direction)) return 0;
  const Vec3f d = toMap(direction);
  const float sinTheta = std::hypot(d.x, d.z) / length(d);
  if (!(sinTheta > 0)) return 0;
  // Uniform in the texel: density width x height in (u, v), over 2 pi^2 sin(theta) per sr.
  return sunPick_.probability(std::size_t(it - sunTexels_.begin())) * float(width_) * float(height_) /
         (2 * kPiF * kPiF * sinTheta);
}

std::optional<EnvironmentSample> Environment::sampleSun(const Vec2f& u) const {
  if (!hasSun()) return std::nullopt;
  float uX = 0;
  const std::uint32_t i = sunTexels_[sunPick_.sample(u.x, &uX)];
  const int x = int(i % std::uint32_t(width_)), y = int(i / std::uint32_t(width_));
  const Vec3f d =
      fromMap(uvToDirection({(float(x) + uX) / float(width_), (float(y) + u.y) / float(height_)}));
  const float density = pdfSun(d);
  if (!(density > 0)) return std::nullopt;
  return EnvironmentSample{d, eval(d), density};
}

Environment Environment::scaled(float k) const {
  if (!(k >= 0) || !std::isfinite(k))
    throw std::invalid_argument("environment intensity must be finite and >= 0");
  Environment e = *this;
  e.constant_ = constant_ * k;
  for (Rgb& t : e.texels_) t = t * k;
  e.averageLuminance_ = averageLuminance_ * k;
  e.averageRadiance_ = averageRadiance_ * k;
  // The sampling density is normalised, so it does not change with k.
  if (!(k > 0)) {
    e.black_ = true;
    e.texels_.clear();
    e.distribution_ = Distribution2D();
    e.sunTexels_.clear();
    e.sunPick_ = Distribution1D();
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, " intensity %g", double(k));
  e.description_ += buf;
  return e;
}

Environment Environment::rotatedAboutY(float degrees) const {
  if (!std::isfinite(degrees)) throw std::invalid_argument("environment rotation must be finite");
  Environment e = *this;
  const double a = double(degrees) * kPi / 180.0;
  // Compose with any earlier rotation (angles about one axis add).
  const double c = std::cos(a), s = std::sin(a);
  e.cosRotation_ = float(c * cosRotation_ - s * sinRotation_);
  e.sinRotation_ = float(s * cosRotation_ + c * sinRotation_);
  char buf[48];
  std::snprintf(buf, sizeof buf, " rotated %gdeg", double(degrees));
  e.description_ += buf;
  return e;
}

// R_y(a) by the right-hand rule: x' = x cos a + z sin a, z' = -x sin a + z cos a.
Vec3f Environment::fromMap(const Vec3f& m) const {
  return {cosRotation_ * m.x + sinRotation_ * m.z, m.y, -sinRotation_ * m.x + cosRotation_ * m.z};
}
Vec3f Environment::toMap(const Vec3f& w) const {
  return {cosRotation_ * w.x - sinRotation_ * w.z, w.y, sinRotation_ * w.x + cosRotation_ * w.z};
}

Vec2f Environment::directionToUv(const Vec3f& d) {
  const float u = 0.5f + std::atan2(d.x, -d.z) / (2 * kPiF);
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPiF;
  return {u - std::floor(u), std::clamp(v, 0.0f, std::nextafter(1.0f, 0.0f))};
}

Vec3f Environment::uvToDirection(const Vec2f& uv) {
  const float theta = kPiF * uv.y, phi = 2 * kPiF * (uv.x - 0.5f);
  const float s = std::sin(theta);
  return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

Rgb Environment::eval(const Vec3f& direction) const {
  if (black_) return {0, 0, 0};
  if (texels_.empty()) return constant_;
  const Vec2f uv = directionToUv(toMap(direction));
  const int x = std::min(int(uv.x * float(width_)), width_ - 1);
  const int y = std::min(int(uv.y * float(height_)), height_ - 1);
  return texels_[std::size_t(y) * width_ + x];
}

std::optional<EnvironmentSample> Environment::sample(const Vec2f& u) const {
  if (black_) return std::nullopt;
  if (texels_.empty()) {
    // Uniform sphere: a constant map has nothing better to offer.
    const float z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPiF * u.y;
    return EnvironmentSample{{r * std::cos(phi), r * std::sin(phi), z}, constant_, 1 / (4 * kPiF)};
  }
  const Vec3f d = fromMap(uvToDirection(distribution_.sample(u, nullptr)));
  // Density and radiance from the direction itself, so that a sample on a texel
  // edge reports the same texel that eval() and pdf() will see for it.
  const float density = pdf(d);
  if (!(density > 0)) return std::nullopt;
  return EnvironmentSample{d, eval(d), density};
}

float Environment::pdf(const Vec3f& direction) const {
  if (black_) return 0;
  if (texels_.empty()) return 1 / (4 * kPiF);
  const Vec3f d = toMap(direction);
  const Vec2f uv = directionToUv(d);
  // sin(theta) from the direction itself: sin(acos(y)) is 0 in float within
  // about 3e-4 rad of a pole, which would reject valid samples there.
  const float sinTheta = std::hypot(d.x, d.z) / length(d);
  if (!(sinTheta > 0)) return 0;
  return distribution_.pdf(uv) / (2 * kPiF * kPiF * sinTheta);
}

}  // namespace lensrt
