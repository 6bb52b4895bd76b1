// A texture image as the scene samples it: linear RGBA texels and how the
// sampler wraps and filters them (glTF's sampler).
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"

namespace lensrt {

// Texels are linear floats, RGBA; colour textures are already decoded from sRGB.
struct Texture {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<Vec4f> texels;  // row-major, row 0 is the top of the image (glTF uv (0,0))
  bool wrapRepeatS = true;    // false: clamp to edge
  bool wrapRepeatT = true;
  bool nearest = false;  // glTF magFilter NEAREST (or minFilter NEAREST* without one); else bilinear
  bool mirrorS = false;  // glTF MIRRORED_REPEAT (only meaningful with wrapRepeatS)
  bool mirrorT = false;
};

}  // namespace lensrt
