// Light arriving from infinitely far away: black, a constant colour, or a
// lat-long (equirectangular) map, importance sampled by luminance x sin(theta).
//
// Lat-long convention (glTF's +Y up): image column u in [0,1) is the azimuth,
// row v in [0,1) the polar angle from +Y (row 0 = straight up). The image
// centre (u, v) = (0.5, 0.5) looks down -Z, glTF's default forward; u grows
// toward +X (so u = 0.75 is +X). The map is piecewise constant per texel.
//
// Importance sampling: a texel is picked with probability proportional to its
// luminance times sin(theta) (the solid angle of its row), a point uniformly
// in it, and the density per solid angle is p(u, v) / (2 pi^2 sin(theta)).
//
// Rotation about +Y by the right-hand rule (counterclockwise seen from above):
// at +90 degrees what the unrotated map shows at -Z (its centre) appears at -X.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "image/image.h"
#include "render/distribution.h"

namespace lensrt {

struct EnvironmentSample {
  Vec3f direction;  // world, unit, toward the environment
  Rgb radiance;
  float pdf;  // solid angle
};

class Environment {
 public:
  Environment() = default;  // black
  static Environment constant(const Rgb& radiance);
  // Uses the R, G, B channels (a single-channel map is grey). Throws
  // std::invalid_argument when the image has no usable channels.
  static Environment latLong(const Image& image);

  // The same light times k >= 0 (--env-intensity).
  Environment scaled(float k) const;
  // The same light turned by `degrees` about +Y (--env-rotate; the sign as above).
  Environment rotatedAboutY(float degrees) const;

  bool isBlack() const { return black_; }
  Rgb eval(const Vec3f& direction) const;
  std::optional<EnvironmentSample> sample(const Vec2f& u) const;
  float pdf(const Vec3f& direction) const;
  // Mean radiance luminance over the sphere: for light selection by power.
  float averageLuminance() const { return averageLuminance_; }
  // Mean radiance over the sphere, per channel (its colour: auto white balance).
  Rgb averageRadiance() const { return averageRadiance_; }
  std::string describe() const { return description_; }

  static Vec2f directionToUv(const Vec3f& d);
  static Vec3f uvToDirection(const Vec2f& uv);

  // The sun of a lat-long map, which lens flare's light pass takes
  // (render/flare_light_pass.h): the texels at least kSunFraction as bright
  // (luminance) as the brightest, when together they cover at most
  // kSunSolidAngle sr; none in a constant map or one whose brightest part is
  // wide (an overcast sky), where camera paths find its ghosts well enough.
  static constexpr float kSunFraction = 0.01f;
  static constexpr float kSunSolidAngle = 0.05f;  // a cone of 7.2 degrees half-angle
  bool hasSun() const { return !sunPick_.empty(); }
  bool inSun(const Vec3f& direction) const;
  // A direction in the sun (world, toward it), picked by the texels'
  // luminance x solid angle, uniform in the texel; its radiance and solid
  // angle density (from the direction itself, as sample() does).
  std::optional<EnvironmentSample> sampleSun(const Vec2f& u) const;
  float pdfSun(const Vec3f& direction) const;

 private:
  // The texel a world direction falls in (a lat-long map).
  std::size_t texelOf(const Vec3f& world) const;
  void findSun();
  // World direction to the unrotated map's frame, and back.
  Vec3f toMap(const Vec3f& world) const;
  Vec3f fromMap(const Vec3f& map) const;

  bool black_ = true;
  Rgb constant_{0, 0, 0};
  int width_ = 0, height_ = 0;
  std::vector<Rgb> texels_;
  Distribution2D distribution_;
  std::vector<std::uint32_t> sunTexels_;  // ascending
  Distribution1D sunPick_;                // over sunTexels_
  float averageLuminance_ = 0;
  Rgb averageRadiance_{0, 0, 0};
  float cosRotation_ = 1, sinRotation_ = 0;
  std::string description_ = "black";
};

}  // namespace lensrt
