// A camera response's own RGB beside the image's. The image is in the output
// space (the film's curves are the camera's times a colour matrix), but a
// camera counts photo-electrons, and its raw file records values, in its own
// channels: the sensor's readout and the raw file go through this.
//
// Camera RGB is the integral of the response's R, G, B curves over the
// light, scaled so that CIE D65 of luminance 1 records green 1 (as
// `--output-space camera` records it).
#pragma once

#include <string>

#include "core/mat3.h"
#include "core/vec.h"
#include "image/image.h"

namespace lensrt {

struct CameraRgb {
  Mat3d toImage;    // camera RGB -> the image's RGB
  Mat3d fromImage;  // the image's RGB -> camera RGB
  // The response curves as quantum efficiency: photo-electrons of a camera
  // value of 1 in each channel, relative to those of an image value of 1 of
  // light at 555 nm (sensor/readout.h's basis), with the curves' peak at the
  // sensor's QE. For D65-coloured light this is the photon count of each
  // channel exactly; for other light, within a few percent (a channel's
  // photons are taken at its mean wavelength under D65).
  Vec3d relativeElectrons{1, 1, 1};
  Vec3d asShotNeutral{1, 1, 1};  // camera RGB of the white balance's illuminant, green 1
  Mat3d xyzToCamera;             // XYZ to camera RGB under D65 (the DNG's ColorMatrix1)
  std::string maker, model;      // the response's camera ("Nikon", "D850"); empty where unknown
};

// R, G, B of every pixel of `image` replaced by `m` times them (no other
// channel changes). Throws std::invalid_argument without R, G, B.
void transformRgb(Image& image, const Mat3d& m);

}  // namespace lensrt
