#include "camera/aperture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.h"
#include "core/sampling.h"

namespace lensrt {

double polygonCircumradiusFactor(int blades) {
  if (blades == 0) return 1.0;
  // Area of a regular n-gon of circumradius R: (n/2) R^2 sin(2 pi / n) = pi r^2.
  return std::sqrt(kPi / (0.5 * blades * std::sin(2.0 * kPi / blades)));
}

Aperture::Aperture(double radius, const ApertureShape& shape) : shape_(shape) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("aperture radius must be positive");
  if (shape.blades < 0 || shape.blades == 1 || shape.blades == 2)
    throw std::invalid_argument("an aperture needs 0 (round) or at least 3 blades");
  circumradius_ = radius * polygonCircumradiusFactor(shape.blades);
  area_ = kPi * radius * radius;
  rotation_ = shape.rotationDegrees * kPi / 180.0;
  inradius_ = shape.blades ? circumradius_ * std::cos(kPi / shape.blades) : circumradius_;
}

Vec2d Aperture::sample(const Vec2d& u) const {
  if (shape_.blades == 0) {
    // The sampler's values are floats, so the float map loses nothing of u.
    const Vec2f d = concentricDisk({float(u.x), float(u.y)});
    return {circumradius_ * double(d.x), circumradius_ * double(d.y)};
  }
  // Equal-area sectors: pick one with u.x, reuse its fraction, then uniform in
  // the triangle (centre, vertex k, vertex k+1).
  const int n = shape_.blades;
  const double scaled = std::min(u.x * n, n - 1e-9);
  const int k = static_cast<int>(scaled);
  const double v = scaled - k;
  const double s = std::sqrt(v);  // barycentric: centre weight 1 - s
  const double a0 = rotation_ + 2.0 * kPi * k / n, a1 = rotation_ + 2.0 * kPi * (k + 1) / n;
  const double b1 = s * (1.0 - u.y), b2 = s * u.y;
  return {circumradius_ * (b1 * std::cos(a0) + b2 * std::cos(a1)),
          circumradius_ * (b1 * std::sin(a0) + b2 * std::sin(a1))};
}

bool Aperture::contains(const Vec2d& p) const {
  const double r = std::hypot(p.x, p.y);
  if (shape_.blades == 0) return r <= circumradius_;
  if (r <= inradius_) return true;
  if (r > circumradius_) return false;
  // Distance to the edge of the sector the point's angle falls in.
  const int n = shape_.blades;
  double phi = std::atan2(p.y, p.x) - rotation_;
  phi -= 2.0 * kPi * std::floor(phi / (2.0 * kPi));
  const double sector = 2.0 * kPi / n;
  const double local = phi - sector * std::floor(phi / sector) - sector / 2.0;  // angle from the edge normal
  return r * std::cos(local) <= inradius_ * (1.0 + 1e-12);
}

std::string describe(const ApertureShape& shape) {
  if (shape.blades == 0) return "round";
  return std::to_string(shape.blades) + " blades";
}

}  // namespace lensrt
