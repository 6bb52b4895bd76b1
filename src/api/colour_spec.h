// How the film records colour: the transport, the sensor's response, the
// white balance and the output's RGB (api/film_colour.h builds the film).
#pragma once

#include <optional>
#include <string>

#include "color/color_space.h"

namespace lensrt {

struct WhiteBalance {
  enum class Kind { None, Auto, Kelvin };
  Kind kind = Kind::None;
  double kelvin = 0.0;  // for Kind::Kelvin
};

// How light travels (--spectral): at four wavelengths per sample, in RGB,
// or auto: spectral where the image depends on wavelengths, RGB elsewhere
// (the plan decides: api/transport_choice.h).
enum class Transport { Spectral, Rgb, Auto };

struct ColourSpec {
  Transport transport = Transport::Auto;
  std::string sensorResponse;                // a response name or a .csv file; empty: cie1931
  std::optional<WhiteBalance> whiteBalance;  // none: the response's default
  // The image's RGB; none: the camera response's own RGB ("camera").
  std::optional<ColorSpaceId> outputSpace = ColorSpaceId::Srgb;
};

}  // namespace lensrt
