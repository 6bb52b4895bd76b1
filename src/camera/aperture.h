// The aperture shape of the models that have one: a disk, or the regular
// polygon that N straight blades form. A polygon has the SAME AREA as the disk
// of the nominal f-number, so the exposure does not depend on the blade count.
#pragma once

#include <string>

#include "core/vec.h"

namespace lensrt {

struct ApertureShape {
  int blades = 0;                // 0: circular; otherwise >= 3
  double rotationDegrees = 0.0;  // first vertex's angle from camera +X toward +Y
};

class Aperture {
 public:
  // `radius`: radius of the disk of equal area (mm). Throws
  // std::invalid_argument for a non-positive radius or 1-2 blades.
  Aperture(double radius, const ApertureShape& shape);

  // Uniformly distributed over the shape, centred on the origin.
  Vec2d sample(const Vec2d& u) const;
  bool contains(const Vec2d& p) const;
  double area() const { return area_; }
  // The disk that just holds the shape (= radius for a disk).
  double circumradius() const { return circumradius_; }
  const ApertureShape& shape() const { return shape_; }

 private:
  ApertureShape shape_;
  double circumradius_ = 0.0;
  double area_ = 0.0;
  double rotation_ = 0.0;  // radians
  double inradius_ = 0.0;
};

// Circumradius / equal-area radius of a regular polygon with `blades` sides
// (1 for a disk): how much wider a stop must open to hold the polygon.
double polygonCircumradiusFactor(int blades);

std::string describe(const ApertureShape& shape);

}  // namespace lensrt
