// Stray light in the full lens (render/flare_light_pass.h).
#pragma once

namespace lensrt {

struct FlareSpec {
  bool on = false;
  int bounces = 2;                 // the most reflections a path takes: 0, 2 or 4
  double barrelReflectance = 0.0;  // the barrel's diffuse reflectance, in [0, 1)
};

}  // namespace lensrt
