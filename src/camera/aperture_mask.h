// A grey-scale mask over the aperture stop (--aperture-mask FILE.png): a
// heart, a star, any shape; white transmits, black blocks, grey transmits
// its value. The full lens (LensCamera) looks up every ray where it crosses
// the stop, so bokeh of out-of-focus lights takes the mask's shape and the
// other apertures still cut it into cat's eyes toward the frame's edge.
//
// Placement: the image's longer side spans the stop's diameter, centred,
// seen from behind the camera looking at the scene (image right = camera +X,
// image top = camera +Y). Lights behind the focus plane then show the mask
// upright, lights in front of it turned by 180 degrees. The stop's disk
// still bounds the light, so the exit-pupil bounds of the round stop hold.
// The mask removes light: the exposure stays that of the f-number.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.h"

namespace lensrt {

class ApertureMask {
 public:
  // width x height transmittances in [0, 1], row by row from the top.
  // Throws std::invalid_argument for an empty image, a wrong count or a
  // value outside [0, 1] (NaN included), or a mask that blocks everything.
  ApertureMask(int width, int height, std::vector<float> transmittance, std::string name);

  // The transmittance at a point (x, y) of the stop plane, relative to its
  // centre, for a stop of radius `stopRadius` (same unit): the nearest
  // texel, 0 outside the image.
  double transmittance(const Vec2d& p, double stopRadius) const;

  // The mean transmittance over the stop's disk (midpoint rule on the texel
  // grid): the fraction of a uniformly lit stop's light the mask passes.
  double meanOverDisk() const;

  int width() const { return width_; }
  int height() const { return height_; }
  // E.g. "heart.png 64x64 #1f2e3d4c5b6a7988": the file name, size and a
  // digest of the values, so the render's identity tells two masks apart.
  std::string describe() const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> values_;
  std::string name_;
  std::uint64_t digest_ = 0;
};

}  // namespace lensrt
