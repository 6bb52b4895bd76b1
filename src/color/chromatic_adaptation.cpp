#include "color/chromatic_adaptation.h"

namespace lensrt {

Mat3d bradfordAdaptation(const Vec3d& sourceWhiteXyz, const Vec3d& targetWhiteXyz) {
  Mat3d bradford;
  bradford.m = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
  const Vec3d s = bradford * sourceWhiteXyz, t = bradford * targetWhiteXyz;
  return *bradford.inverse() * Mat3d::diagonal({t.x / s.x, t.y / s.y, t.z / s.z}) * bradford;
}

}  // namespace lensrt
